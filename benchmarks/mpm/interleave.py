#!/usr/bin/python3
"""Interleaved comparison of two Google Benchmark binaries (old and new builds of bench_mpm_step or
bench_ice): ROUNDS rounds, each running OLD then NEW on the cases of FILTER; prints per case the
median wall time per iteration of each, the ratio new / old and the spread. On a shared machine
only medians of interleaved rounds compare (docs/benchmarks.md).

    /usr/bin/python3 benchmarks/mpm/interleave.py OLD NEW ROUNDS FILTER
"""
import csv
import io
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
                              "--benchmark_format=csv"], capture_output=True, text=True, check=True).stdout
        rows = list(csv.reader(io.StringIO(out[out.index("name,"):])))
        for row in rows[1:]:
            d = dict(zip(rows[0], row))
            res.setdefault(d["name"], {}).setdefault(tag, []).append(float(d["real_time"]))
for name, v in res.items():
    mo, mn = statistics.median(v["old"]), statistics.median(v["new"])
    print(f"{name:28s} old {mo:7.2f}  new {mn:7.2f}  new/old {mn / mo:.3f}   "
          f"old {min(v['old']):.2f}-{max(v['old']):.2f} new {min(v['new']):.2f}-{max(v['new']):.2f}")
