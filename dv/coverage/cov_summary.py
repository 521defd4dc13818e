#!/usr/bin/env python3
"""dv/coverage/cov_summary.py - one line per RTL module of a merged Verilator
coverage file (make rtl-coverage, tests/cov/rtl-coverage.sh; issue 27).

Reads coverage.dat as verilator_coverage writes it (one point a line:
C '<key>\\x02<value>\\x01...' COUNT), keeps the points of the files under
RTL_DIR (the bench's own are not the design's), merges each point over the
instances of its module (hit when any instance hit it), and sorts them:

  line     every v_line point (a statement block, an if or else arm, a case
           item): all must be hit;
  branch   the v_line points that are an if, else or case arm (a subset);
  toggle   every v_toggle point (one per bit of a signal): >= 95 % per module.

A hole may be waived in WAIVERS (tab-separated: kind, module (a glob), pattern,
reason; kind line also waives the branch of that point).  The pattern is a glob
over the point's id, '[' and ']' plain: for a toggle the signal's bit as
Verilator names it ("occ[17]"; "SIG[LO:HI]" waives bits LO..HI of the signals
the glob SIG names), for a line or branch "ARM: SOURCE" (ARM is Verilator's
comment: block, if, else, case, ...; SOURCE the point's first source line,
trimmed).  A waiver that
matches no hole is reported as stale (the design changed: review it).

usage: cov_summary.py COVERAGE.dat RTL_DIR WAIVERS [--require] [--holes FILE]
The last column gives toggle bits and lines hit or waived (percent).
Exit 1 with --require when an unwaived line or branch hole is left, a
module's toggle coverage is under 95 %, or a waiver is stale.
"""
import fnmatch
import os
import re
import sys

BRANCH_ARMS = {"if", "else", "elsif", "case", "casez", "casex", "default"}


def parse(path):
    pts = {}
    for raw in open(path, "rb"):
        line = raw.decode("latin-1").rstrip("\n")
        if not line.startswith("C '"):
            continue
        m = re.match(r"C '(.*)' (\d+)$", line)
        if not m:
            continue
        kv = {}
        for field in m.group(1).split("\x01"):
            if "\x02" in field:
                k, v = field.split("\x02", 1)
                kv[k] = v
        yield kv, int(m.group(2))


def main():
    args = sys.argv[1:]
    require = "--require" in args
    holes_file = None
    if "--holes" in args:
        holes_file = args[args.index("--holes") + 1]
        del args[args.index("--holes"):args.index("--holes") + 2]
    args = [a for a in args if a != "--require"]
    if len(args) != 3:
        raise SystemExit(__doc__)
    dat, rtl_dir, waivers_path = args
    rtl_dir = os.path.realpath(rtl_dir)
    src_cache = {}

    def src_line(f, ln):
        if f not in src_cache:
            try:
                src_cache[f] = open(f).read().split("\n")
            except OSError:
                src_cache[f] = []
        lines = src_cache[f]
        return " ".join(lines[ln - 1].split()) if 0 < ln <= len(lines) else ""

    # (module, kind, id) -> count
    merged = {}
    fname = {}
    for kv, n in parse(dat):
        f = kv.get("f", "")
        if os.path.dirname(os.path.realpath(f)) != rtl_dir:
            continue
        # a module is its file (one per file in rtl/); an include file (ef_rooks.vh) stands alone
        mod = os.path.basename(f)[:-2] if f.endswith(".v") else os.path.basename(f)
        fname[mod] = os.path.basename(f)
        page = kv.get("page", "")
        o = kv.get("o", "")
        ln = int(kv.get("l", "0") or 0)
        if page.startswith("v_toggle"):
            key = (mod, "toggle", o)
        elif page.startswith("v_line") or page.startswith("v_branch"):
            key = (mod, "line", "%s: %s" % (o, src_line(f, ln)), ln, kv.get("n", ""))
        else:
            key = (mod, "user", o, ln)
        merged[key] = merged.get(key, 0) + n

    waivers = []
    if os.path.exists(waivers_path):
        for ln in open(waivers_path):
            if ln.startswith("#") or not ln.strip() or ln.startswith("kind\t"):
                continue
            parts = ln.rstrip("\n").split("\t")
            if len(parts) < 4 or parts[0] not in ("line", "branch", "toggle") or not parts[3].strip():
                raise SystemExit("cov_summary: %s: a waiver needs kind (line|branch|toggle), module, pattern "
                                 "and a reason: %r" % (waivers_path, ln))
            waivers.append([parts[0], parts[1], parts[2], parts[3], 0])

    def matches(pat, pid):
        # "SIG[LO:HI]": bits LO..HI of the signals SIG (a glob) names; else a glob over the id
        # in which '[' and ']' are plain characters
        m = re.fullmatch(r"(.*)\[(\d+):(\d+)\]", pat)
        if m:
            b = re.fullmatch(r"(.*)\[(\d+)\]", pid)
            return bool(b) and fnmatch.fnmatchcase(b.group(1), m.group(1)) and \
                int(m.group(2)) <= int(b.group(2)) <= int(m.group(3))
        esc = pat.replace("[", "\x00").replace("]", "[]]").replace("\x00", "[[]")
        return fnmatch.fnmatchcase(pid, esc)

    def waived(mod, kind, pid):
        for w in waivers:
            if fnmatch.fnmatchcase(mod, w[1]) and (w[0] == kind or (kind == "line" and w[0] == "branch")) \
                    and matches(w[2], pid):
                w[4] += 1
                return True
        return False

    mods = sorted({k[0] for k in merged})

    def cw(c):
        """toggle bits hit or waived, and lines hit or waived, as 'T % / L %'"""
        t = (c["toggle"][1] + c["toggle"][2]) * 1000 // c["toggle"][0] if c["toggle"][0] else 1000
        ln = (c["line"][1] + c["line"][2]) * 1000 // c["line"][0] if c["line"][0] else 1000
        return "%d.%d/%d.%d" % (*divmod(t, 10), *divmod(ln, 10))
    bad = 0
    holes = []
    tot = {"line": [0, 0, 0], "branch": [0, 0, 0], "toggle": [0, 0, 0]}
    print("%-12s %22s %22s %24s %8s %10s" % ("module", "lines", "branches", "toggle bits", "waived",
                                            "+waived"))
    for mod in mods:
        c = {"line": [0, 0, 0], "branch": [0, 0, 0], "toggle": [0, 0, 0]}   # points, hit, waived
        for key, n in merged.items():
            if key[0] != mod or key[1] == "user":
                continue
            kind, pid = key[1], key[2]
            arm = pid.split(":", 1)[0]
            kinds = [kind] + (["branch"] if kind == "line" and arm in BRANCH_ARMS else [])
            w = n == 0 and waived(mod, kind, pid)
            for k in kinds:
                c[k][0] += 1
                c[k][1] += n > 0
                c[k][2] += w
            if n == 0:
                where = ("rtl/%s:%d" % (fname[mod], key[3])) if kind == "line" else ("rtl/%s" % fname[mod])
                holes.append("%s %s %s %s%s" % ("waived" if w else "HOLE", kind, where, pid,
                                                 "" if not w else ""))
        for k in c:
            tot[k] = [a + b for a, b in zip(tot[k], c[k])]

        def pct(v):
            return "%d/%d (%d.%d %%)" % (v[1], v[0], *divmod(v[1] * 1000 // v[0], 10)) if v[0] else "-"
        nw = c["line"][2] + c["toggle"][2]
        print("%-12s %22s %22s %24s %8d %10s" % (mod, pct(c["line"]), pct(c["branch"]), pct(c["toggle"]), nw,
                                                 cw(c)))
        if c["line"][0] - c["line"][1] - c["line"][2] > 0:
            bad += 1
        tcov = (c["toggle"][1] + c["toggle"][2]) * 1000 // c["toggle"][0] if c["toggle"][0] else 1000
        if tcov < 950:
            bad += 1
    def pct(v):
        return "%d/%d (%d.%d %%)" % (v[1], v[0], *divmod(v[1] * 1000 // v[0], 10)) if v[0] else "-"
    print("%-12s %22s %22s %24s %8d %10s" % ("all", pct(tot["line"]), pct(tot["branch"]), pct(tot["toggle"]),
                                             tot["line"][2] + tot["toggle"][2], cw(tot)))
    unw = [h for h in holes if h.startswith("HOLE")]
    print("holes: %d line/branch and %d toggle bits unhit; %d of them waived (dv/coverage/waivers.tsv), %d not"
          % (sum(1 for h in holes if " line " in h), sum(1 for h in holes if " toggle " in h),
             len(holes) - len(unw), len(unw)))
    for h in [h for h in unw if " line " in h][:200]:
        print("  " + h)
    nt = [h for h in unw if " toggle " in h]
    for h in nt[:40]:
        print("  " + h)
    if len(nt) > 40:
        print("  ... and %d more toggle holes (--holes FILE lists them all)" % (len(nt) - 40))
    stale = [w for w in waivers if w[4] == 0]
    for w in stale:
        print("stale waiver (matches no hole): %s %s %s" % (w[0], w[1], w[2]))
    if holes_file:
        with open(holes_file, "w") as f:
            f.write("\n".join(holes) + "\n")
    if require and (bad or stale):
        print("rtl-coverage: targets not met: every line and branch hit or waived, toggles >= 95 %% per module, "
              "no stale waiver (%d modules short, %d stale waivers)" % (bad, len(stale)))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
