# shellcheck shell=bash
# shellcheck disable=SC2086,SC2154 # sourced by rtl-test.sh: its root, work, have_vl; file lists split on purpose
# tests/rtl/blocks_a.sh - sourced by tests/rtl/run.sh (uses its submit,
# count, $EF, $work, $root, $TB, $have_vl): the front of the pipeline in RTL,
# block by block, each fed from its upstream interface's expected hex and
# checked cycle for cycle with `edgeflag check --cycles` on its own output:
#
#   DEC   (ef_dec.v)              cmd.stim.hex     -> seg    (dv/tb/tb_dec.v)
#   SETUP (ef_setup.v + ef_div.v + ef_slb_ram.v) seg.expected.hex -> et_wr  (dv/tb/tb_setup.v)
#   ETM   (ef_etm.v)              et_wr.expected.hex -> et_rd (dv/tb/tb_etm.v)
#
# on two shared SVGs at 40x30 (8/16/32 samples x both rules) and eleven
# `edgeflag gen` level-1 cases (directed: top/bottom clip, extreme
# coordinates, long edges, canvas 1x1, ...; and random ones) at 8/16/32
# samples, under Icarus; one SVG configuration under Verilator.  The benches
# take every bit position from ef_ifaces.vh, which `edgeflag vectors
# --rtl-headers` writes here first (docs/vectors.md section 8), and the
# SystemVerilog package is checked by dv/tb/tb_ifaces_pkg.sv.  Lint:
# verilator --lint-only -Wall and iverilog -g2005 -Wall silent for every
# block at NS 8/16/32.  Negative control: the divider without its floor
# correction (the RTL variant dv/faults/div_floor.sed) must fail with the first mismatch on
# et_wr with a quotient field marked: x or qs (the fault skips the quotient's
# correction in both lanes; which one shows first depends on the first edge
# whose remainder needs it).

RTLA=$root/rtl
A_DEC="$RTLA/ef_dec.v"
A_SETUP="$RTLA/ef_setup.v $RTLA/ef_div.v $RTLA/ef_slb_ram.v"
A_ETM="$RTLA/ef_etm.v $RTLA/ef_slb_ram.v"
inc=$work/inc
if ! "$EF" vectors --rtl-headers -o "$inc" >"$work/logs/rtl_headers.log" 2>&1 ||
   [ ! -s "$inc/ef_ifaces.vh" ] || [ ! -s "$inc/ef_ifaces_pkg.sv" ]; then
    cat "$work/logs/rtl_headers.log"; echo "FAIL blocks: edgeflag vectors --rtl-headers"; fail=$((fail + 1))
fi

# ------------------------------------------------------------------ lint
lint_a() {
    local ns=$1 out top files g
    for top in ef_dec ef_setup ef_etm; do
        case $top in
            ef_dec)   files=$A_DEC;   g="-GW_MAX=320 -GH_MAX=240" ;;
            ef_setup) files=$A_SETUP; g="-GNS=$ns" ;;
            ef_etm)   files=$A_ETM;   g="-GNS=$ns -GH_MAX=240 -GE_MAX=512" ;;
        esac
        [ -f "${files%% *}" ] || continue
        if [ $have_vl = 1 ]; then
            # shellcheck disable=SC2086
            out=$(verilator --lint-only -Wall -I"$RTLA" $g --top-module $top $files 2>&1)
            [ -z "$out" ] || { echo "$out"; echo "RESULT FAIL lint $top NS=$ns: verilator -Wall is not silent"; return; }
        fi
        out=$(iverilog -g2005 -Wall -I"$RTLA" ${g//-G/-P$top.} -s $top -o /dev/null $files 2>&1)
        [ -z "$out" ] || { echo "$out"; echo "RESULT FAIL lint $top NS=$ns: iverilog -g2005 -Wall is not silent"; return; }
    done
    echo "RESULT PASS lint ef_dec, ef_setup + ef_div, ef_etm NS=$ns: verilator -Wall and iverilog -g2005 -Wall silent"
}
for ns in 8 16 32; do submit "lint_a_$ns" lint_a "$ns"; done

# ------------------------------------------------------- block benches
# blk_run SIM TB D NS OUT_IFACE [FAULT]: build and run one bench on vector
# set D (on the RTL variant with dv/faults/FAULT.sed when given); prints the
# bench's result line, returns 0 when it says PASS.
blk_run() {
    local sim=$1 tb=$2 d=$3 ns=$4 out=$5 def=${6:-} files params=() o src=$RTLA
    local nc ns_ nw
    nc=$(count "$d/cmd.stim.hex"); ns_=$(count "$d/seg.expected.hex"); nw=$(count "$d/et_wr.expected.hex")
    case $tb in
        tb_dec)   files=$A_DEC;   params=(NCMD="$nc") ;;
        tb_setup) files=$A_SETUP; params=(NS="$ns" NCMD="$nc" NSEG="$ns_") ;;
        # H_MAX 4096: the cases' canvases are at most 2048 tall, and the
        # slot sweep after reset takes H_MAX cycles
        tb_etm)   files=$A_ETM;   params=(NS="$ns" H_MAX=4096 NCMD="$nc" NWR="$nw" NRD="$(count "$d/et_rd.expected.hex")"
                                          NPLOT="$(count "$d/plot.expected.hex")") ;;
    esac
    o=$d/$sim-$tb$def
    mkdir -p "$o"
    if [ -n "$def" ]; then
        src=$o/rtl
        bash "$root/dv/rtl-variant.sh" "$src" "$def" || { echo "$tb: FAIL the RTL variant $def"; return 1; }
        files=${files//$RTLA/$src}
    fi
    local plus=(+cmd="$d/cmd.stim.hex" +seg_in="$d/seg.expected.hex" +et_wr_in="$d/et_wr.expected.hex"
                +plot="$d/plot.expected.hex" +et_rd_exp="$d/et_rd.expected.hex")
    case $tb in
        tb_dec)   plus+=(+seg="$o/seg.actual.hex") ;;
        tb_setup) plus+=(+et_wr="$o/et_wr.actual.hex") ;;
        tb_etm)   plus+=(+et_rd="$o/et_rd.actual.hex") ;;
    esac
    if [ "$sim" = iv ]; then
        local p=() kv
        for kv in "${params[@]}"; do p+=(-P"$tb.$kv"); done
        # shellcheck disable=SC2086
        iverilog -g2005 -I"$inc" -I"$src" -I"$TB" "${p[@]}" -o "$o/tb.vvp" "$TB/$tb.v" $files >"$o/build.log" 2>&1 ||
            { cat "$o/build.log"; echo "$tb: FAIL compile"; return 1; }
        vvp -n "$o/tb.vvp" "${plus[@]}" >"$o/sim" 2>&1
    else
        local g=() kv
        for kv in "${params[@]}"; do g+=(-G"$kv"); done
        # shellcheck disable=SC2086
        verilator --binary --timing -Wno-fatal -Wno-WIDTH -I"$inc" -I"$src" -I"$TB" --Mdir "$o/obj" --top-module "$tb" \
            "${g[@]}" "$TB/$tb.v" $files -o tb >"$o/build.log" 2>&1 ||
            { tail -n 20 "$o/build.log"; echo "$tb: FAIL verilator build"; return 1; }
        "$o/obj/tb" "${plus[@]}" >"$o/sim" 2>&1
    fi
    grep -E "^$tb: (DONE|FAIL)" "$o/sim" || { tail -n 5 "$o/sim"; echo "$tb: FAIL no result line"; }
    grep -q "^$tb: DONE" "$o/sim"
}

# blk NAME INPUT NS RULE SIMS [vectors options...]: vectors (hex), then DEC,
# SETUP and ETM benches under each of SIMS (iv, vl), each output checked.
blk() {
    local name=$1 input=$2 ns=$3 rule=$4 sims=$5; shift 5
    local d=$work/blk/$name sim tb out n=0
    mkdir -p "$d"
    [ "$rule" = scene ] || set -- --rule "$rule" "$@"
    "$EF" vectors "$input" -o "$d" --samples "$ns" --formats hex \
        --interfaces cmd,seg,et_wr,et_rd,plot "$@" >"$d/vectors.log" 2>&1 ||
        { cat "$d/vectors.log"; echo "RESULT FAIL blk $name: edgeflag vectors"; return; }
    for sim in $sims; do
        for tb in tb_dec tb_setup tb_etm; do
            case $tb in tb_dec) out=seg ;; tb_setup) out=et_wr ;; tb_etm) out=et_rd ;; esac
            [ -f "$TB/$tb.v" ] || continue
            blk_run "$sim" "$tb" "$d" "$ns" "$out" || { echo "RESULT FAIL blk $name: $sim $tb"; return; }
            "$EF" check "$d/$out.expected.hex" "$d/$sim-$tb/$out.actual.hex" --cycles --errors 5 ||
                { echo "RESULT FAIL blk $name: $sim $tb: edgeflag check --cycles on $out"; return; }
            n=$((n + 1))
        done
    done
    echo "RESULT PASS blk $name ($sims): $n benches, seg $(count "$d/seg.expected.hex"), et_wr $(count "$d/et_wr.expected.hex"), et_rd $(count "$d/et_rd.expected.hex") transactions cycle-exact"
}

for svg in stress_pixi_fill_rule_star_nonzero lion; do
    for ns in 8 16 32; do
        for r in nonzero evenodd; do
            submit "blk_${svg}_${ns}_$r" blk "$svg-40x30/$ns/$r" "$root/tests/data/svg/$svg.svg" "$ns" "$r" iv --size 40x30
        done
    done
done
a_cases="outside-all-sides outside-crossing limit-corners limit-long-edges long-exact near-horizontal
         border-sample-rows canvas-1x1 empty-shapes many-shapes"
a_list=()
for n in $a_cases; do
    f=$(awk -F'\t' -v n="$n" '$3 == "directed" && $5 == n { print $2; exit }' "$work/gen/index.tsv")
    if [ -z "$f" ]; then echo "FAIL blocks: no directed case named $n in index.tsv"; fail=$((fail + 1)); continue; fi
    a_list+=("$n:$f")
done
f=$(awk -F'\t' '$3 == "random" { print $2 }' "$work/gen/index.tsv" | sed -n 5p)
[ -n "$f" ] && a_list+=("random-${f%.scene}:$f")
k=0
for c in "${a_list[@]}"; do
    i=0
    for ns in 8 16 32; do
        # each case under the three rule settings, one per sample count
        case $(( (k + i) % 3 )) in 0) r=nonzero ;; 1) r=evenodd ;; *) r=scene ;; esac
        i=$((i + 1))
        submit "blk_${c%%:*}_${ns}_$r" blk "${c%%:*}/$ns/$r" "$work/gen/${c#*:}" "$ns" "$r" iv
    done
    k=$((k + 1))
done
[ $have_vl = 1 ] && submit blk_vl blk "vl/lion-40x30/16/nonzero" "$root/tests/data/svg/lion.svg" 16 nonzero vl --size 40x30

# The SystemVerilog package under Verilator: struct widths and field offsets.
pkg_vl() {
    local o=$work/pkg_vl
    mkdir -p "$o"
    verilator --binary -Wno-fatal --Mdir "$o/obj" --top-module tb_ifaces_pkg "$inc/ef_ifaces_pkg.sv" \
        "$TB/tb_ifaces_pkg.sv" -o tb >"$o/build.log" 2>&1 ||
        { tail -n 20 "$o/build.log"; echo "RESULT FAIL ef_ifaces_pkg.sv: verilator build"; return; }
    "$o/obj/tb" | tee "$o/sim"
    grep -q '^tb_ifaces_pkg: PASS' "$o/sim" &&
        echo "RESULT PASS ef_ifaces_pkg.sv (generated): $(sed -n 's/^tb_ifaces_pkg: PASS //p' "$o/sim")" ||
        echo "RESULT FAIL ef_ifaces_pkg.sv: tb_ifaces_pkg"
}
[ $have_vl = 1 ] && submit pkg_vl pkg_vl

# The bench can fail: the divider without its floor correction.
fault_div() {
    local d=$work/blk/fault-div out
    mkdir -p "$d"
    "$EF" vectors "$root/tests/data/svg/lion.svg" -o "$d" --samples 8 --size 40x30 --formats hex \
        --interfaces cmd,seg,et_wr,et_rd,plot >"$d/vectors.log" 2>&1 || { echo "RESULT FAIL fault-div: vectors"; return; }
    blk_run iv tb_setup "$d" 8 et_wr div_floor
    out=$("$EF" check "$d/et_wr.expected.hex" "$d/iv-tb_setupdiv_floor/et_wr.actual.hex" --cycles --errors 1 2>/dev/null)
    local rc=$?
    echo "$out"
    if [ $rc = 1 ] && echo "$out" | grep -Eq '^[^ ]*et_wr.actual.hex:[0-9]+: et_wr: cycle [0-9]+, .*fields differ: .*actual .* (x|qs)=-?[0-9]+\*'; then
        echo "RESULT PASS fault-div: the divider without its floor correction fails --cycles, first mismatch on et_wr, a quotient (x or qs) marked"
    else
        echo "RESULT FAIL fault-div: check exit $rc, expected 1 with the first mismatch on et_wr, x or qs marked"
    fi
}
submit fault_div fault_div

# Streams the hardware cannot take are refused before they run, naming the
# file and line: a canvas over W_MAX, a shape over E_MAX edges, cycle stamps
# that go backwards.
refuse() {
    local d=$work/blk/refuse n nw nr np want
    mkdir -p "$d"
    "$EF" vectors "$root/tests/data/svg/lion.svg" -o "$d" --samples 8 --size 40x30 --formats hex \
        --interfaces cmd,seg,et_wr,et_rd,plot >"$d/vectors.log" 2>&1 || { echo "RESULT FAIL refuse: vectors"; return; }
    n=$(count "$d/cmd.stim.hex"); nw=$(count "$d/et_wr.expected.hex")
    nr=$(count "$d/et_rd.expected.hex"); np=$(count "$d/plot.expected.hex")
    # 1. FRAME 40x30 on a DEC built for W_MAX = 32
    iverilog -g2005 -I"$inc" -I"$RTLA" -I"$TB" -Ptb_dec.NCMD="$n" -Ptb_dec.W_MAX=32 -o "$d/dec.vvp" "$TB/tb_dec.v" $A_DEC &&
        vvp -n "$d/dec.vvp" +cmd="$d/cmd.stim.hex" +seg="$d/seg.actual.hex" >"$d/sim1" 2>&1
    want="^tb_dec: FAIL $d/cmd.stim.hex: word 0 \\(line 5\\): FRAME 40x30 is over W_MAX x H_MAX = 32x16384\$"
    grep -Eq "$want" "$d/sim1" || { cat "$d/sim1"; echo "RESULT FAIL refuse: canvas over W_MAX not refused as expected"; return; }
    # 2. a shape of more than E_MAX = 4 edges
    # shellcheck disable=SC2086
    iverilog -g2005 -I"$inc" -I"$RTLA" -I"$TB" -Ptb_etm.NWR="$nw" -Ptb_etm.NRD="$nr" -Ptb_etm.NPLOT="$np" -Ptb_etm.E_MAX=4 \
        -o "$d/etm.vvp" "$TB/tb_etm.v" $A_ETM &&
        vvp -n "$d/etm.vvp" +et_wr_in="$d/et_wr.expected.hex" +et_rd_exp="$d/et_rd.expected.hex" \
            +plot="$d/plot.expected.hex" +et_rd="$d/et_rd.actual.hex" >"$d/sim2" 2>&1
    grep -Eq "^tb_etm: FAIL $d/et_wr.expected.hex: word [0-9]+ \\(line [0-9]+\\): a shape of more than E_MAX=4 edges\$" "$d/sim2" ||
        { cat "$d/sim2"; echo "RESULT FAIL refuse: a shape over E_MAX not refused as expected"; return; }
    # 3. commands 3 and 4 swapped: line 9 (word 4) has the smaller stamp
    awk '!/^\/\// { k++; if (k == 4) { held = $0; next } if (k == 5) { print; print held; next } } { print }' \
        "$d/cmd.stim.hex" >"$d/swapped.hex"
    iverilog -g2005 -I"$inc" -I"$RTLA" -I"$TB" -Ptb_dec.NCMD="$n" -o "$d/dec2.vvp" "$TB/tb_dec.v" $A_DEC &&
        vvp -n "$d/dec2.vvp" +cmd="$d/swapped.hex" +seg="$d/seg2.actual.hex" >"$d/sim3" 2>&1
    grep -Eq "^tb_dec: FAIL $d/swapped.hex: word 4 \\(line 9\\): cycle stamp [0-9]+ does not increase" "$d/sim3" ||
        { cat "$d/sim3"; echo "RESULT FAIL refuse: stamps going backwards not refused as expected"; return; }
    echo "RESULT PASS refuse: a canvas over W_MAX, a shape over E_MAX edges and stamps going backwards are refused, naming file and line"
}
submit refuse refuse
