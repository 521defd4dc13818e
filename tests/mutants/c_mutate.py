#!/usr/bin/env python3
"""tests/mutants/c_mutate.py - first-order mutants of a C file (issue 27: the
board engine and the host link, tests/mutants/c-mutants.sh).

  c_mutate.py list FILE.c            one line per mutant: id, line, operator, original, mutated
  c_mutate.py write FILE.c ID OUT.c  writes mutant ID of FILE.c to OUT.c

Operators: cmp (< <=, > >=, == !=, each way), logic (&& ||), const (a decimal
literal + 1, and - 1 when not 0).  Comments, strings, character literals and
preprocessor lines are left alone; so are the array sizes of declarations
(a literal right after '[' that follows an identifier in a declaration would
change a layout, not a behaviour: only literals in statements are mutated, i.e.
inside a function body).
"""
import re
import sys

TOK = re.compile(r"""
    (?P<ws>\s+)
  | (?P<com>//[^\n]*|/\*.*?\*/)
  | (?P<pp>^\#[^\n]*(?:\\\n[^\n]*)*)
  | (?P<str>"(?:[^"\\\n]|\\.)*"|'(?:[^'\\\n]|\\.)*')
  | (?P<num>0[xX][0-9a-fA-F]+[uUlL]*|\d+[uUlL]*)
  | (?P<id>[A-Za-z_]\w*)
  | (?P<op><<=|>>=|->|\+\+|--|<<|>>|<=|>=|==|!=|&&|\|\||[-+*/%<>=!~&|^?:;,.(){}\[\]])
""", re.S | re.X | re.M)

FLIP = {"<": "<=", "<=": "<", ">": ">=", ">=": ">", "==": "!=", "!=": "==", "&&": "||", "||": "&&"}


def mutants(src):
    out = []
    depth = 0
    pos = 0
    line = 1
    prev = ""
    for m in TOK.finditer(src):
        kind, text = m.lastgroup, m.group()
        if m.start() != pos:
            raise SystemExit("c_mutate: cannot read at line %d" % line)
        pos = m.end()
        if kind == "op" and text == "{":
            depth += 1
        elif kind == "op" and text == "}":
            depth -= 1
        if depth > 0 and kind == "op" and text in FLIP:
            # '<' and '>' of a shift are their own tokens; a template does not exist in C
            op = "logic" if text in ("&&", "||") else "cmp"
            out.append((m.start(), m.end(), line, op, text, FLIP[text]))
        if depth > 0 and kind == "num" and prev != "[" and re.fullmatch(r"\d+[uUlL]*", text):
            digits = re.match(r"\d+", text).group()
            suffix = text[len(digits):]
            v = int(digits)
            if len(digits) > 1 and digits.startswith("0"):
                pass  # octal: leave it
            else:
                out.append((m.start(), m.end(), line, "const", text, "%d%s" % (v + 1, suffix)))
                if v > 0:
                    out.append((m.start(), m.end(), line, "const", text, "%d%s" % (v - 1, suffix)))
        if kind not in ("ws", "com"):
            prev = text
        line += text.count("\n")
    return out


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    src = open(sys.argv[2]).read()
    ms = mutants(src)
    if sys.argv[1] == "list":
        for i, (a, b, line, op, old, new) in enumerate(ms, 1):
            print("%d\t%d\t%s\t%s\t%s" % (i, line, op, old, new))
    elif sys.argv[1] == "write":
        a, b, line, op, old, new = ms[int(sys.argv[3]) - 1]
        open(sys.argv[4], "w").write(src[:a] + new + src[b:])
    else:
        raise SystemExit(__doc__)


if __name__ == "__main__":
    main()
