#!/usr/bin/python3
"""Interleaved comparison of two Google Benchmark binaries (old and new builds of bench_mpm_step or
bench_ice): ROUNDS rounds, each running OLD then NEW on the cases of FILTER; prints per case the
median wall time per iteration of each, the ratio new / old and the spread. On a shared machine
only medians of interleaved rounds compare (docs/benchmarks.md).

    /usr/bin/python3 benchmarks/mpm/interleave.py OLD NEW ROUNDS FILTER
"""
import json
import statistics
import subprocess
import sys

if len(sys.argv) != 5:
    sys.exit(__doc__)
old, new, rounds, filt = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
res = {}
for _ in range(rounds):
    for tag, binary in (("old", old), ("new", new)):
        out = subprocess.run([binary, f"--benchmark_filter={filt}", "--benchmark_min_time=0.5",
                              "--benchmark_format=json"], capture_output=True, text=True, check=True).stdout
        for b in json.loads(out)["benchmarks"]:
            res.setdefault(b["name"], {}).setdefault(tag, []).append(float(b["real_time"]))
for name, v in res.items():
    mo, mn = statistics.median(v["old"]), statistics.median(v["new"])
    print(f"{name:28s} old {mo:7.2f}  new {mn:7.2f}  new/old {mn / mo:.3f}   "
          f"old {min(v['old']):.2f}-{max(v['old']):.2f} new {min(v['new']):.2f}-{max(v['new']):.2f}")
