#!/usr/bin/python3
"""polar2d's figures over variants of the case. Its runs are chaotic (any change in the last
bits of a measure changes later decisions, and the single case's q min moves by +-0.03), so a
change to the 2D remesher is judged over the last passes of several variants of the field.

  bench/polar2d_variants.py [--riemesh BIN] [--case polar2d] [--s 0.85,0.9,1.0,1.1]
                            [--h0 0.0009,0.0011] [--passes 8] [--first 5] [--jobs 2]

Runs ../shared/bench/iterate.py on CASE:s=S,h0=H for every S and H (--hgrad 0, as
bench/adapt2d_cases.sh) and prints, over passes FIRST..PASSES of all of them, the mean, median and
worst of the fraction of edges in [1/sqrt2, sqrt2] and of q min, and the mean of q mean."""
import argparse
import concurrent.futures
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
HARNESS = os.path.join(HERE, "..", "..", "shared", "bench")


def run(case, binary, passes, workdir):
    cmd = [sys.executable, os.path.join(HARNESS, "iterate.py"), case, "--workdir", workdir,
           "--passes", str(passes), "--cmd", f"{binary} adapt {{mesh}} --metric {{sol}} -o {{out}} -q --hgrad 0"]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return [json.loads(line) for line in out.splitlines() if line.startswith("{")]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--riemesh", default=os.path.join(HERE, "..", "build", "riemesh"))
    ap.add_argument("--case", default="polar2d")
    ap.add_argument("--s", default="0.85,0.9,1.0,1.1")
    ap.add_argument("--h0", default="0.0009,0.0011")
    ap.add_argument("--passes", type=int, default=8)
    ap.add_argument("--first", type=int, default=5)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    binary = os.path.abspath(a.riemesh)
    variants = [f"{a.case}:s={s},h0={h}" for s in a.s.split(",") for h in a.h0.split(",")]
    with tempfile.TemporaryDirectory() as tmp, concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        jobs = [pool.submit(run, v, binary, a.passes, os.path.join(tmp, str(i)))
                for i, v in enumerate(variants)]
        rows = [r for j in jobs for r in j.result() if a.first <= r.get("pass", -1) <= a.passes]
    if not rows:
        sys.exit("no pass in range")
    band = [100.0 * r["len_in"] for r in rows]
    qmin = [r["q_min"] for r in rows]
    print(f"{len(variants)} variants, passes {a.first}-{a.passes}: {len(rows)} meshes")
    print(f"in band   mean {statistics.mean(band):.2f}%  median {statistics.median(band):.2f}%  worst {min(band):.2f}%")
    print(f"q min     mean {statistics.mean(qmin):.3f}  median {statistics.median(qmin):.3f}  worst {min(qmin):.3f}")
    print(f"q mean    mean {statistics.mean(r['q_mean'] for r in rows):.3f}")


if __name__ == "__main__":
    main()
