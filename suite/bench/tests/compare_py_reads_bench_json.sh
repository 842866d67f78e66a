#!/bin/sh
# Google Benchmark's own comparison tool reads bench.json
# (docs/bench-format.md): two `lightcts bench --quick` runs on one backend,
# then `compare.py benchmarks A/bench.json B/bench.json` must exit 0 and name
# every benchmark both files time. With RUN_A, the folder of an earlier
# `lightcts bench --quick` run on BACKEND (ctest's bench.command-quick), no
# run is made here: that run is compared with a copy of itself. What is
# checked is how compare.py and lightcts read the file, which a second run
# of the same code would write in the same form (its times aside).
#
# usage: compare_py_reads_bench_json.sh LIGHTCTS SCENES_DIR OUT_DIR [BACKEND [RUN_A]]
# Exit 77 (ctest's skip) when compare.py (Debian libbenchmark-tools) or a
# Python with SciPy (python3-scipy) is missing, or the backend is not here.
set -u
lightcts=$1
scenes=$2
out=$3
backend=${4:-vulkan}
run_a=${5:-}

compare=${LIGHTCTS_COMPARE_PY:-/usr/share/benchmark/compare.py}
if [ ! -f "$compare" ]; then
  echo "LIGHTCTS_SKIP: $compare is missing (apt-get install libbenchmark-tools)"
  exit 77
fi
# compare.py imports scipy.stats; Debian's python3-scipy is for /usr/bin/python3,
# which another python3 first in PATH may not see.
python=
for candidate in /usr/bin/python3 python3; do
  if "$candidate" -c 'import scipy.stats' >/dev/null 2>&1; then
    python=$candidate
    break
  fi
done
if [ -z "$python" ]; then
  echo "LIGHTCTS_SKIP: no python3 with scipy (apt-get install python3-scipy)"
  exit 77
fi

rm -rf "$out"
mkdir -p "$out"
runs="a b"
if [ -n "$run_a" ]; then
  if [ ! -f "$run_a/bench.json" ]; then
    echo "FAIL: no bench.json in $run_a"
    exit 1
  fi
  cp -r "$run_a" "$out/a"
  cp -r "$run_a" "$out/b"
  runs=""
fi
for run in $runs; do
  "$lightcts" bench --quick --backend "$backend" --scenes "$scenes" --out "$out/$run" >"$out/$run.log" 2>&1
  status=$?
  if [ $status -eq 3 ]; then
    echo "LIGHTCTS_SKIP: $backend is not here:"
    cat "$out/$run.log"
    exit 77
  fi
  if [ $status -ne 0 ]; then
    echo "FAIL: lightcts bench ($run) exited $status:"
    cat "$out/$run.log"
    exit 1
  fi
done

"$python" "$compare" --no-color benchmarks "$out/a/bench.json" "$out/b/bench.json" >"$out/compare.txt" 2>&1
status=$?
cat "$out/compare.txt"
if [ $status -ne 0 ]; then
  echo "FAIL: compare.py exited $status"
  exit 1
fi

# lightcts's own reader (reports/bench_data.cpp) takes the per-backend
# arrays only, not their flat copy as well: each benchmark once.
"$lightcts" bench compare "$out/a/bench.json" "$out/b/bench.json" >"$out/bench-compare.txt" 2>&1
twice=$(awk '$1 ~ /^(frame|frame_readback|pipeline|prepare)\// {print $1}' "$out/bench-compare.txt" | sort | uniq -d)
if [ -n "$twice" ]; then
  echo "FAIL: lightcts bench compare lists these twice (it read the flat copy too):"
  echo "$twice"
  exit 1
fi

# Every timed benchmark of both flat arrays (name, real_time, cpu_time and
# time_unit: what compare.py compares) must be a row of its report, the
# frame benchmarks of the backend and the CPU preparation among them.
"$python" - "$out/a/bench.json" "$out/b/bench.json" "$out/compare.txt" "$backend" <<'EOF'
import json, sys
a, b, report, backend = sys.argv[1:5]
def timed(path):
    with open(path) as f:
        bench = json.load(f)
    names = []
    for entry in bench["benchmarks"]:
        if all(k in entry for k in ("name", "real_time", "cpu_time", "time_unit")) and entry["name"] not in names:
            names.append(entry["name"])
    return names
in_b = set(timed(b))
names = [n for n in timed(a) if n in in_b]
rows = set()
with open(report) as f:
    for line in f:
        fields = line.split()
        if fields:
            rows.add(fields[0])
missing = [n for n in names if n not in rows]
frame = [n for n in names if n.startswith("frame/" + backend + "/")]
prepare = [n for n in names if n.startswith("prepare/cpu/")]
print(f"compare.py: {len(names)} benchmarks in both files, {len(frame)} frame/{backend}, {len(prepare)} prepare/cpu; "
      f"{len(missing)} not in its report")
if missing:
    print("FAIL: not in compare.py's report:", *missing[:20], sep="\n  ")
    sys.exit(1)
if not frame or not prepare:
    print("FAIL: expected frame/" + backend + "/... and prepare/cpu/... benchmarks in both files")
    sys.exit(1)
if "OVERALL_GEOMEAN" not in rows:
    print("FAIL: compare.py's report has no OVERALL_GEOMEAN row")
    sys.exit(1)
EOF
