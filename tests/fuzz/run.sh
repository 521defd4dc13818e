#!/usr/bin/env bash
# tests/fuzz/run.sh - runs the libFuzzer targets of tests/fuzz/ (built by
# `make fuzz-build` into BUILD/fuzz/).  One target at a time, one process
# each (no -jobs/-workers): the machine is shared.
#
#   run.sh BUILD smoke  SECONDS TARGET...   short run on a scratch copy of the corpus (CI)
#   run.sh BUILD fuzz   SECONDS TARGET...   longer run; new inputs kept in WORK/corpus/TARGET
#   run.sh BUILD replay 0       TARGET...   every file of tests/fuzz/{corpus,regress}/TARGET once
#   run.sh BUILD merge  0       TARGET...   minimise corpus + WORK/corpus into tests/fuzz/corpus
#
# WORK is BUILD-work (FUZZ_WORK overrides): the fuzzers' own corpora, logs and
# findings survive a rebuild of BUILD.  A crash, leak, sanitizer report,
# timeout (> 10 s for one input) or broken property aborts the target; its
# input is saved as WORK/artifacts/TARGET/crash-* (copy it to
# tests/fuzz/regress/TARGET/ once fixed).  Ends with "N passed, M failed"
# (targets); fuzz/smoke append one line per target to WORK/fuzz-stats.tsv:
# date, mode, target, executions, seconds, result.
set -u
cd "$(dirname "$0")/../.." || exit 1
build=${1:?usage: run.sh BUILD MODE SECONDS TARGET...}
mode=${2:?mode}
secs=${3:?seconds}
shift 3
[ $# -gt 0 ] || { echo "fuzz: no targets"; exit 2; }
here=tests/fuzz
work_root=${FUZZ_WORK:-$build-work}
mkdir -p "$work_root/logs" "$work_root/artifacts"
stats=$work_root/fuzz-stats.tsv

# ASan: leaks are bugs too; UBSan: stop at the first report with a trace.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

pass=0 fail=0
for t in "$@"; do
    bin=$build/fuzz/fuzz_$t
    log=$work_root/logs/$t.$mode.log
    [ -x "$bin" ] || { echo "fuzz: $bin missing (make fuzz-build)"; fail=$((fail + 1)); continue; }
    corpus=$here/corpus/$t regress=$here/regress/$t
    mkdir -p "$work_root/artifacts/$t"
    opts=(-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1
          -artifact_prefix="$work_root/artifacts/$t/")
    [ -f "$here/$t.dict" ] && opts+=(-dict="$here/$t.dict")
    [ -f "$here/$t.options" ] && read -r -a extra <"$here/$t.options" && opts+=("${extra[@]}")
    seeds=()
    [ -d "$corpus" ] && seeds+=("$corpus")
    [ -d "$regress" ] && seeds+=("$regress")
    case $mode in
    smoke|fuzz)
        if [ "$mode" = smoke ]; then
            work=$work_root/scratch/$t; rm -rf "$work"
        else
            work=$work_root/corpus/$t
        fi
        mkdir -p "$work"
        "$bin" "${opts[@]}" -max_total_time="$secs" "$work" "${seeds[@]}" >"$log" 2>&1
        rc=$?
        runs=$(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -Eo '[0-9]+$' | tail -n 1)
        runs=${runs:-$(grep -Eo 'Done [0-9]+ runs' "$log" | grep -Eo '[0-9]+' | tail -n 1)}
        if [ $rc -eq 0 ] && grep -q '^Done [0-9]* runs' "$log"; then
            pass=$((pass + 1))
            echo "fuzz: $t: ${runs:-?} executions in ${secs} s, clean ($(find "$work" -type f | wc -l) inputs in $work)"
            printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$mode" "$t" "${runs:-0}" "$secs" clean >>"$stats"
        else
            fail=$((fail + 1))
            echo "fuzz: $t: FAILED (exit $rc) after ${runs:-?} executions; log $log"
            grep -E '^(==[0-9]+==ERROR|SUMMARY|fuzz|.*runtime error|artifact_prefix|Test unit written)' "$log" | head -n 12 | sed 's/^/    /'
            printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$mode" "$t" "${runs:-0}" "$secs" FAILED >>"$stats"
        fi
        ;;
    replay)
        files=()
        for d in "${seeds[@]}"; do
            while IFS= read -r -d '' f; do files+=("$f"); done < <(find "$d" -type f ! -name 'README*' -print0 | sort -z)
        done
        if [ ${#files[@]} -eq 0 ]; then
            echo "fuzz: $t: no corpus"; fail=$((fail + 1)); continue
        fi
        # Files (not directories) are each executed once, whole, and nothing is mutated.
        "$bin" "${opts[@]}" "${files[@]}" >"$log" 2>&1
        rc=$?
        ran=$(grep -c '^Executed ' "$log")
        if [ $rc -eq 0 ] && [ "$ran" -eq ${#files[@]} ]; then
            pass=$((pass + 1))
            echo "fuzz: $t: replayed $ran corpus and regression inputs, clean"
        else
            fail=$((fail + 1))
            echo "fuzz: $t: replay FAILED (exit $rc, $ran of ${#files[@]} inputs ran); log $log"
            grep -E '^(Running:|==[0-9]+==ERROR|SUMMARY|fuzz|.*runtime error)' "$log" | tail -n 12 | sed 's/^/    /'
        fi
        ;;
    merge)
        new=$work_root/merged/$t; rm -rf "$new"; mkdir -p "$new" "$work_root/corpus/$t"
        if "$bin" "${opts[@]}" -merge=1 "$new" "${seeds[0]:-$work_root/corpus/$t}" "$work_root/corpus/$t" >"$log" 2>&1; then
            rm -rf "$corpus"; mkdir -p "$corpus"
            # The repository keeps a small seed corpus (a few hundred KB in all):
            # past the target's budget, the smallest inputs of the minimised set
            # are kept (they carry most of the features per byte; libFuzzer
            # rebuilds the rest in seconds).  Content-addressed names.
            case $t in svg) budget=200 ;; scene|render) budget=60 ;; *) budget=30 ;; esac
            total=0
            while IFS= read -r f; do
                sz=$(stat -c %s "$f")
                [ $((total + sz)) -gt $((budget * 1024)) ] && break
                total=$((total + sz))
                cp "$f" "$corpus/$(sha1sum "$f" | cut -c1-40)"
            done < <(find "$new" -type f -printf '%s %p\n' | sort -n | cut -d' ' -f2-)
            pass=$((pass + 1))
            echo "fuzz: $t: corpus minimised to $(find "$corpus" -type f | wc -l) inputs, $(du -sk --apparent-size "$corpus" | cut -f1) KiB"
        else
            fail=$((fail + 1)); echo "fuzz: $t: merge FAILED; log $log"; tail -n 5 "$log"
        fi
        ;;
    *) echo "fuzz: unknown mode $mode"; exit 2 ;;
    esac
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
