#!/usr/bin/env python3
"""dv/mutants/rtl_mutate.py - mutants of the synthesizable RTL (issue 27).

Reads rtl/*.v (never writes there) and writes, into an output folder, copies
of the files in which every mutation site is a mutant schema: the original
expression and each mutated one side by side, chosen at run time by the
plusarg +mut=K (0, or no plusarg: the original design).  One build of the
bench then runs any mutant, which is what makes a mutation run affordable on
two cores.  Also writes mutants.tsv: id, file, line, operator, key (a stable
name: file, operator, the original and mutated text, the occurrence), the
original and the mutated text.

Operators (docs/testing.md, "RTL mutants"):
  cmp    a comparison flipped at its boundary (< <=, > >=) or negated (== !=)
  const  a constant off by one (+1, and -1 when it is not 0; not in bit
         selects, replication counts, parameters or case labels)
  mux    the two arms of a ?: swapped
  stuck  a valid or ready output stuck at 0 and at 1
  reset  the reset inverted in an if condition (rst -> !rst)
  hold   a register that never loads (q <= d becomes q <= q): the update of a
         pipeline register dropped

Initial blocks, for headers, parameters, and functions that a parameter
calls (they must stay constant expressions) are left alone.  The planted
faults are not in rtl/ (they are sed scripts, dv/faults/*.sed, that
dv/rtl-variant.sh applies to a copy); should an `ifdef EF_FAULT_*` branch
ever appear, its code is skipped too.

usage: rtl_mutate.py OUT_DIR FILE.v|FILE.vh...    (prints the number of mutants; a .vh file is
       a fragment included in a module's body, whose ef_mut it uses)
"""
import os
import re
import sys

TOKEN = re.compile(r"""
    (?P<ws>\s+)
  | (?P<lc>//[^\n]*)
  | (?P<bc>/\*.*?\*/)
  | (?P<dir>`[A-Za-z_]\w*)
  | (?P<str>"(?:[^"\\]|\\.)*")
  | (?P<num>(?:\d[\d_]*)?'[sS]?[bodhBODH][0-9a-fA-F_xzXZ?]+|\d[\d_]*)
  | (?P<id>[A-Za-z_$][\w$]*)
  | (?P<op><<<|>>>|===|!==|==|!=|<=|>=|&&|\|\||<<|>>|\+:|-:|\*\*|~&|~\||~\^|\^~|[-+*/%<>!~&|^?:;,.(){}\[\]@#=])
""", re.S | re.X)

CMP_FLIP = {"<": "<=", "<=": "<", ">": ">=", ">=": ">", "==": "!=", "!=": "=="}
OPEN = {"(": ")", "[": "]", "{": "}"}
KEYWORDS = {"begin", "end", "else", "if", "case", "casez", "casex", "endcase", "for", "default", "always",
            "initial", "assign", "wire", "reg", "integer", "localparam", "parameter", "function", "endfunction",
            "module", "endmodule", "input", "output", "inout", "generate", "endgenerate", "genvar", "signed"}


class Tok:
    __slots__ = ("kind", "text", "pos", "line", "dead")

    def __init__(self, kind, text, pos, line):
        self.kind, self.text, self.pos, self.line, self.dead = kind, text, pos, line, False


def tokenize(src):
    toks, pos, line = [], 0, 1
    while pos < len(src):
        m = TOKEN.match(src, pos)
        if not m:
            raise SystemExit("rtl_mutate: cannot read at line %d: %r" % (line, src[pos:pos + 20]))
        kind = m.lastgroup
        if kind not in ("ws", "lc", "bc"):
            toks.append(Tok(kind, m.group(), pos, line))
        line += m.group().count("\n")
        pos = m.end()
    # dead code: an `ifdef EF_FAULT_* branch, should one appear (rtl/ has none)
    stack = []
    i = 0
    while i < len(toks):
        t = toks[i]
        if t.kind == "dir" and t.text in ("`ifdef", "`ifndef"):
            name = toks[i + 1].text
            fault = name.startswith("EF_FAULT")
            stack.append((fault, t.text == "`ifdef"))
            t.dead = True
            toks[i + 1].dead = True
            i += 2
            continue
        if t.kind == "dir" and t.text == "`else" and stack:
            f, live_is_else = stack[-1]
            stack[-1] = (f, not live_is_else)
            t.dead = True
        elif t.kind == "dir" and t.text == "`endif" and stack:
            stack.pop()
            t.dead = True
        else:
            # in an `ifdef EF_FAULT branch (state True) the code is dead
            t.dead = any(f and s for f, s in stack)
        i += 1
    return toks


def match_close(toks, i):
    """index of the token closing the group opened at i"""
    want, depth = OPEN[toks[i].text], 0
    for j in range(i, len(toks)):
        if toks[j].text in OPEN:
            depth += 1
        elif toks[j].text in (")", "]", "}"):
            depth -= 1
            if depth == 0:
                return j
    raise SystemExit("rtl_mutate: unbalanced %s at line %d" % (toks[i].text, toks[i].line))


def region_end(toks, i, stop_comma):
    """first index at or after i of ';' (or ',' when stop_comma) at depth 0, or of a
    bracket closing a group opened before i"""
    depth = 0
    for j in range(i, len(toks)):
        x = toks[j].text
        if x in OPEN:
            depth += 1
        elif x in (")", "]", "}"):
            depth -= 1
            if depth < 0:
                return j
        elif depth == 0 and (x == ";" or (stop_comma and x == ",")):
            return j
    raise SystemExit("rtl_mutate: no end of statement after line %d" % toks[i].line)


def parse_lvalue(toks, i):
    """end index (exclusive) of an lvalue at i, or None"""
    t = toks[i]
    if t.text == "{":
        return match_close(toks, i) + 1
    if t.kind != "id" or t.text in KEYWORDS or t.text.startswith("$"):
        return None
    j = i + 1
    while j < len(toks) and toks[j].text == "[":
        j = match_close(toks, j) + 1
    return j


class Region:
    """an expression region [a, b) of tokens: an assignment's right side or a condition"""

    def __init__(self, a, b, kind, lhs=None, nba=False):
        self.a, self.b, self.kind, self.lhs, self.nba = a, b, kind, lhs, nba


def find_regions(toks, const_funcs, in_module=False):
    """in_module: the file is a fragment included in a module's body (ef_rooks.vh)"""
    regions = []
    n = len(toks)
    i = 0
    stmt = False          # inside an always or function body
    depth = 0             # begin/case nesting in it
    while i < n:
        t = toks[i]
        x = t.text
        if t.dead or t.kind == "dir":
            # `include "FILE" (ef_ifaces.vh, ef_ns.vh): the name goes with it
            i += 2 if t.text == "`include" and i + 1 < n and toks[i + 1].kind == "str" else 1
            continue
        if x == "module":
            # skip the header: name, #( ... ), ( ... ) ;
            j = i + 2
            if toks[j].text == "#":
                j = match_close(toks, j + 1) + 1
            if toks[j].text == "(":
                j = match_close(toks, j) + 1
            regions.append(Region(j + 1, j + 1, "header"))  # where ef_mut is declared
            i = j + 1
            in_module, stmt = True, False
            continue
        if not in_module:
            i += 1
            continue
        if x in ("endfunction", "endmodule", "endgenerate", "generate"):
            i += 1
            stmt, depth = False, 0
            continue
        if x in ("localparam", "parameter", "genvar", "integer", "input", "output", "inout"):
            i = region_end(toks, i, False) + 1
            continue
        if x == "function":
            # function NAME ... endfunction; skip it when a parameter needs it constant
            j = i + 1
            while toks[j].kind != "id" or toks[j].text in ("signed", "integer", "automatic"):
                if toks[j].text == "[":
                    j = match_close(toks, j)
                j += 1
            name = toks[j].text
            if name in const_funcs:
                while toks[i].text != "endfunction":
                    i += 1
                continue
            i = region_end(toks, j, False) + 1
            stmt, depth = True, 0
            continue
        if stmt and x in ("reg", "wire"):
            i = region_end(toks, i, False) + 1
            continue
        if x == "initial":
            j = i + 1
            if toks[j].text == "begin":
                depth = 0
                while True:
                    if toks[j].text in ("begin", "case", "casez", "casex"):
                        depth += 1
                    elif toks[j].text in ("end", "endcase"):
                        depth -= 1
                        if depth == 0:
                            break
                    j += 1
                i = j + 1
            else:
                i = region_end(toks, j, False) + 1
            stmt = False
            continue
        if x in ("wire", "reg") and not stmt:
            # declaration; wire NAME = RHS is a continuous assignment
            j = i + 1
            while toks[j].text == "signed" or toks[j].text == "[":
                if toks[j].text == "[":
                    j = match_close(toks, j)
                j += 1
            e = region_end(toks, i, False)
            if x == "wire" and toks[j].kind == "id" and toks[j + 1].text == "=":
                b = region_end(toks, j + 2, True)
                regions.append(Region(j + 2, b, "rhs", lhs=toks[j].text))
            i = e + 1
            continue
        if x == "assign":
            lv = parse_lvalue(toks, i + 1)
            if lv is not None and toks[lv].text == "=":
                b = region_end(toks, lv + 1, False)
                regions.append(Region(lv + 1, b, "rhs", lhs=" ".join(tk.text for tk in toks[i + 1:lv])))
                i = b + 1
                continue
        if x == "always":
            j = i + 1
            if toks[j].text == "@":
                j += 1
                j = match_close(toks, j) + 1 if toks[j].text == "(" else j + 1
            i, stmt, depth = j, True, 0
            continue
        if stmt and x == "begin":
            i, depth = i + 1, depth + 1
            if toks[i].text == ":":       # a named block
                i += 2
            continue
        if not stmt and x in ("if", "for"):   # generate if / for: constant, left alone
            i = match_close(toks, i + 1) + 1
            continue
        if not stmt and x in ("begin", "end", "else"):
            i += 1
            if x == "begin" and toks[i].text == ":":
                i += 2
            continue
        if stmt and x in ("end", "endcase"):
            i, depth = i + 1, depth - 1
            stmt = depth > 0
            continue
        if stmt and x == "else":
            i += 1
            continue
        if stmt and x == ";":
            i += 1
            stmt = depth > 0
            continue
        if stmt and x == "if":
            c = match_close(toks, i + 1)
            regions.append(Region(i + 2, c, "cond"))
            i = c + 1
            continue
        if stmt and x in ("case", "casez", "casex"):
            i, depth = match_close(toks, i + 1) + 1, depth + 1
            continue
        if stmt and x == "for":
            i = match_close(toks, i + 1) + 1
            continue
        if stmt:
            lv = parse_lvalue(toks, i)
            if lv is not None and toks[lv].text in ("<=", "="):
                b = region_end(toks, lv + 1, False)
                regions.append(Region(lv + 1, b, "rhs", lhs=" ".join(tk.text for tk in toks[i:lv]),
                                      nba=toks[lv].text == "<="))
                i = b + 1
                stmt = depth > 0
                continue
            # a case label, an instance, a function's declarations: to the next ':' or ';'
            j, d = i, 0
            while j < n:
                y = toks[j].text
                if y in OPEN:
                    d += 1
                elif y in (")", "]", "}"):
                    d -= 1
                elif d == 0 and y in (":", ";"):
                    break
                j += 1
            if j < n and toks[j].text == ";":
                stmt = depth > 0
            i = j + 1
            continue
        # module item we do not mutate (an instance): to its ';'
        i = region_end(toks, i, False) + 1
    return regions


def ternary_arms(toks, q, b):
    """(colon, end) of the ?: whose '?' is at q, within [.., b)"""
    depth, nest = 0, 0
    colon = None
    for j in range(q + 1, b):
        y = toks[j].text
        if y in OPEN:
            depth += 1
        elif y in (")", "]", "}"):
            depth -= 1
            if depth < 0:
                return None
        elif depth == 0 and y == "?":
            nest += 1
        elif depth == 0 and y == ":":
            if nest == 0:
                colon = j
                break
            nest -= 1
    if colon is None:
        return None
    depth, nest = 0, 0
    for j in range(colon + 1, b):
        y = toks[j].text
        if y in OPEN:
            depth += 1
        elif y in (")", "]", "}"):
            depth -= 1
            if depth < 0:
                return colon, j
        elif depth == 0 and y == ",":
            return colon, j
        elif depth == 0 and y == "?":
            nest += 1
        elif depth == 0 and y == ":":
            if nest == 0:
                return colon, j
            nest -= 1
    return colon, b


def const_bump(text, d):
    m = re.fullmatch(r"(\d*)'([sS]?)([bodhBODH])([0-9a-fA-F_]+)", text)
    if m:
        w = int(m.group(1)) if m.group(1) else 32
        base = {"b": 2, "o": 8, "d": 10, "h": 16}[m.group(3).lower()]
        v = int(m.group(4).replace("_", ""), base) + d
        if v < 0 or v >= (1 << w):
            return None
        digits = {2: format(v, "b"), 8: format(v, "o"), 10: str(v), 16: format(v, "x")}[base]
        return "%s'%s%s%s" % (m.group(1), m.group(2), m.group(3), digits)
    if re.fullmatch(r"\d[\d_]*", text):
        v = int(text.replace("_", "")) + d
        return str(v) if v >= 0 else None
    return None


def in_replication_count(toks, k, b):
    """token k lies in a parenthesised replication count: {(N*64){...}}"""
    depth = 0
    for j in range(k + 1, b):
        y = toks[j].text
        if y in OPEN:
            depth += 1
        elif y in (")", "]", "}"):
            if depth == 0:
                return y == ")" and j + 1 < b and toks[j + 1].text == "{"
            depth -= 1
    return False


def mutants_of(toks, r, src):
    """[(op, token span a..b, replacement text)] of region r"""
    out = []
    if any(toks[k].kind == "dir" or toks[k].dead for k in range(r.a, r.b)):
        return out
    depth_br = 0
    for k in range(r.a, r.b):
        t = toks[k]
        if t.text == "[":
            depth_br += 1
        elif t.text == "]":
            depth_br -= 1
        if t.text in CMP_FLIP and depth_br == 0:
            out.append(("cmp", k, k + 1, CMP_FLIP[t.text]))
        if t.kind == "num" and depth_br == 0 and not (k + 1 < r.b and toks[k + 1].text == "{") \
                and not in_replication_count(toks, k, r.b):
            for d in (1, -1):
                nt = const_bump(t.text, d)
                if nt is not None:
                    out.append(("const", k, k + 1, nt))
        if t.text == "?" and depth_br == 0:
            arms = ternary_arms(toks, k, r.b)
            if arms:
                colon, end = arms
                a1 = src[toks[k + 1].pos:toks[colon - 1].pos + len(toks[colon - 1].text)]
                a2 = src[toks[colon + 1].pos:toks[end - 1].pos + len(toks[end - 1].text)]
                if a1.strip() != a2.strip():
                    out.append(("mux", k + 1, end, "(%s) : (%s)" % (a2, a1)))
        if r.kind == "cond" and t.text == "rst":
            out.append(("reset", k, k + 1, "(!rst)"))
    if r.kind == "rhs" and r.lhs and re.search(r"(valid|ready)$", r.lhs.split("[")[0].strip()):
        text = " ".join(toks[k].text for k in range(r.a, r.b))
        for v in ("1'b0", "1'b1"):
            if text != v:         # stuck at what it already is: no mutant
                out.append(("stuck", r.a, r.b, v))
    if r.kind == "rhs" and r.nba and r.lhs:
        out.append(("hold", r.a, r.b, r.lhs))
    return out


def span_text(src, toks, a, b):
    return src[toks[a].pos:toks[b - 1].pos + len(toks[b - 1].text)]


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    out_dir, files = sys.argv[1], sys.argv[2:]
    os.makedirs(out_dir, exist_ok=True)
    rows = []
    mid = 0
    for path in files:
        src = open(path).read()
        toks = tokenize(src)
        # functions that a parameter or localparam calls must stay constant
        const_funcs = set()
        funcs = {toks[k + 1].text for k in range(len(toks) - 1) if toks[k].text == "function"}
        funcs |= {toks[k + 2].text for k in range(len(toks) - 2) if toks[k].text == "function" and toks[k + 1].text == "["}
        for k, t in enumerate(toks):
            if t.text in ("localparam", "parameter"):
                e = region_end(toks, k, False)
                const_funcs |= {toks[j].text for j in range(k, e) if toks[j].text in funcs}
        regions = find_regions(toks, const_funcs, in_module=path.endswith(".vh"))
        base = os.path.basename(path)
        edits = []      # (start char, end char, new text)
        seen = {}
        for r in regions:
            if r.kind == "header":
                pos = toks[r.a - 1].pos + 1
                edits.append((pos, pos, "\n    // mutant selector (dv/mutants/rtl_mutate.py): +mut=K, 0 = the design\n"
                              "    reg [31:0] ef_mut;\n"
                              "    initial begin if (!$value$plusargs(\"mut=%d\", ef_mut)) ef_mut = 32'd0; end\n"))
                continue
            ms = mutants_of(toks, r, src)
            if not ms:
                continue
            orig = span_text(src, toks, r.a, r.b)
            chain = []
            for op, a, b, new in ms:
                mutated = src[toks[r.a].pos:toks[a].pos] + new + src[toks[b - 1].pos + len(toks[b - 1].text):
                                                                     toks[r.b - 1].pos + len(toks[r.b - 1].text)]
                mid += 1
                old = span_text(src, toks, a, b)
                one = lambda s: " ".join(s.split())
                key0 = "%s|%s|%s|%s" % (base, op, one(old), one(new))
                seen[key0] = seen.get(key0, 0) + 1
                key = "%s|%d" % (key0, seen[key0])
                rows.append((mid, base, toks[a].line, op, key, one(old), one(new)))
                chain.append("(ef_mut == 32'd%d) ? (%s) : " % (mid, mutated))
            new_text = "(" + "".join(chain) + "(" + orig + "))"
            edits.append((toks[r.a].pos, toks[r.b - 1].pos + len(toks[r.b - 1].text), new_text))
        edits.sort()
        outsrc, last = [], 0
        for a, b, txt in edits:
            if a < last:
                raise SystemExit("rtl_mutate: overlapping regions in %s" % path)
            outsrc.append(src[last:a])
            outsrc.append(txt)
            last = b
        outsrc.append(src[last:])
        with open(os.path.join(out_dir, base), "w") as f:
            f.write("// GENERATED by dv/mutants/rtl_mutate.py from %s: mutant schemata, not for synthesis\n" % path)
            f.write("".join(outsrc))
    with open(os.path.join(out_dir, "mutants.tsv"), "w") as f:
        f.write("id\tfile\tline\top\tkey\toriginal\tmutated\n")
        for r in rows:
            f.write("\t".join(str(x).replace("\t", " ") for x in r) + "\n")
    print(mid)


if __name__ == "__main__":
    main()
