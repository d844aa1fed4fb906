#!/bin/sh
# A random run split into processes (--jobs, testbenches/common/bench_jobs.h) gives the same totals
# as the same run in one process: per case, samples and mismatches summed over the merged summary
# rows; exit status 0 both ways; a split run with mismatches injected into process 0 exits 1.
#   check_jobs.sh <bench program> <stimuli> <jobs> [extra args...]
set -u
prog=$1; n=$2; jobs=$3; shift 3
dir=$(mktemp -d) || exit 1
trap 'rm -rf "$dir"' EXIT
"$prog" --random "$n" --jobs 1 --summary "$dir/one.tsv" "$@" > "$dir/one.out" || { cat "$dir/one.out"; echo "single-process run failed"; exit 1; }
"$prog" --random "$n" --jobs "$jobs" --summary "$dir/split.tsv" "$@" > "$dir/split.out" || { cat "$dir/split.out"; echo "split run failed"; exit 1; }
grep -q "in $jobs processes -> PASS" "$dir/split.out" || { cat "$dir/split.out"; echo "the run was not split into $jobs processes"; exit 1; }
totals() { awk -F'\t' '{ s[$1 "\t" $2] += $3; m[$1 "\t" $2] += $4 } END { for (k in s) print k "\t" s[k] "\t" m[k] }' "$1" | sort; }
totals "$dir/one.tsv" > "$dir/one.tot"
totals "$dir/split.tsv" > "$dir/split.tot"
echo "one process:"; cat "$dir/one.tot"
echo "$jobs processes:"; cat "$dir/split.tot"
[ -s "$dir/one.tot" ] || { echo "no summary rows"; exit 1; }
cmp -s "$dir/one.tot" "$dir/split.tot" || { echo "totals differ"; exit 1; }
"$prog" --random "$n" --jobs "$jobs" --inject-mismatch 0 --inject-count 256 "$@" > "$dir/inject.out" 2>&1
rc=$?
[ "$rc" -eq 1 ] || { cat "$dir/inject.out"; echo "split run with 256 injected mismatches exited $rc, not 1"; exit 1; }
grep -q "in $jobs processes -> FAIL" "$dir/inject.out" || { echo "the injected run was not split"; exit 1; }
echo "same totals; injected mismatches fail the split run"
