#!/usr/bin/python3
"""Surface remeshing figures (issue #6): for every surface of ../shared/data/surf and each
--hausd (a fraction of the bounding-box diagonal, as in PEERS.md's mmgs table), run
`riemesh adapt`, then measure the two-sided Hausdorff distance to the input with
`riemesh distance` (lattice order 4 on every triangle), the triangle count, the minimum and mean
quality (4√3 A / Σ l²), the validity (`riemesh check`), the wall time and the CPU time
(user + system of the run, robust to a loaded machine; medians of --runs).

usage: bench/surface_bench.py [--riemesh build/riemesh] [--data ../shared/data/surf]
                              [--hausd 0.002,0.0005] [--runs 3] [--json OUT.json] [--aniso]
                              [--reference OTHER_BINARY] [--surfaces fandisk,...]

--reference runs another build of riemesh on the same command, alternating with --riemesh run by
run, and prints the wall time ratio: on a shared machine whose speed drifts from minute to minute
the ratio is steadier than either time (the wall times of the two are medians of the same
minutes). The wall and CPU times are those of the whole command, file reading and writing
included, as mmgs's in PEERS.md.
"""
import argparse, json, math, os, statistics, subprocess, sys, tempfile, time

# mmgs 5.8 figures from PEERS.md: (output tris, measured/hausd, q min, q mean, wall s)
MMGS = {
    ("bunny", 0.002): (8630, 1.506, 0.154, 0.957, 0.27),
    ("bunny", 0.0005): (48686, 6.15, 0.272, 0.96, 1.15),
    ("elephant", 0.002): (11082, 1.282, 0.444, 0.948, 0.32),
    ("elephant", 0.0005): (52872, 4.325, 0.417, 0.959, 1.45),
    ("fandisk", 0.002): (2820, 1.036, 0.499, 0.93, 0.17),
    ("fandisk", 0.0005): (8808, 1.479, 0.2, 0.942, 0.28),
    ("rotor", 0.002): (6220, 15.189, 0.239, 0.937, 0.2),
    ("rotor", 0.0005): (25190, 61.921, 0.373, 0.951, 0.73),
}


def bbox_diagonal(path):
    with open(path) as f:
        lines = f.read().split("\n")
    i = next(k for k, l in enumerate(lines) if l.strip() == "Vertices")
    n = int(lines[i + 1])
    pts = [list(map(float, lines[i + 2 + k].split()[:3])) for k in range(n)]
    return math.sqrt(sum((max(p[c] for p in pts) - min(p[c] for p in pts)) ** 2 for c in range(3)))


def quality(path):
    with open(path) as f:
        lines = f.read().split("\n")
    i = next(k for k, l in enumerate(lines) if l.strip() == "Vertices")
    n = int(lines[i + 1])
    pts = [list(map(float, lines[i + 2 + k].split()[:3])) for k in range(n)]
    j = next(k for k, l in enumerate(lines) if l.strip() == "Triangles")
    m = int(lines[j + 1])
    qs = []
    for k in range(m):
        a, b, c = (pts[int(x) - 1] for x in lines[j + 2 + k].split()[:3])
        ab = [b[d] - a[d] for d in range(3)]
        ac = [c[d] - a[d] for d in range(3)]
        bc = [c[d] - b[d] for d in range(3)]
        cr = [ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]]
        area = 0.5 * math.sqrt(sum(x * x for x in cr))
        l2 = sum(x * x for x in ab) + sum(x * x for x in ac) + sum(x * x for x in bc)
        qs.append(4 * math.sqrt(3) * area / l2)
    return m, min(qs), sum(qs) / m


def main():
    ap = argparse.ArgumentParser()
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--riemesh", default=os.path.join(here, "..", "build", "riemesh"))
    ap.add_argument("--data", default=os.path.join(here, "..", "..", "shared", "data", "surf"))
    ap.add_argument("--hausd", default="0.002,0.0005")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--json")
    ap.add_argument("--aniso", action="store_true", help="anisotropic geometric metric")
    ap.add_argument("--reference", help="another riemesh binary, timed alternately on each case")
    ap.add_argument("--surfaces", default="bunny,elephant,fandisk,rotor")
    a = ap.parse_args()
    rows = []
    tmp = tempfile.mkdtemp()
    ref_head = "| reference wall s | ratio " if a.reference else ""
    print("| surface | hausd | input tris | output tris | measured / hausd | q min | q mean | valid | wall s | cpu s "
          + ref_head + "| mmgs tris | mmgs measured/hausd | mmgs q min | mmgs wall s |")
    print("|" + "---|" * (14 + (2 if a.reference else 0)))
    for name in a.surfaces.split(","):
        src = os.path.join(a.data, name + ".mesh")
        diag = bbox_diagonal(src)
        for frac in [float(x) for x in a.hausd.split(",")]:
            hausd = frac * diag
            out = os.path.join(tmp, "%s_%g.mesh" % (name, frac))
            times, cpus, ref_times = [], [], []
            for _ in range(a.runs):
                if a.reference:
                    t0 = time.perf_counter()
                    subprocess.run([a.reference, "adapt", src, "-o", out + ".ref.mesh", "--hausd", repr(hausd),
                                    "--quiet"] + (["--aniso"] if a.aniso else []), check=True)
                    ref_times.append(time.perf_counter() - t0)
                t0 = time.perf_counter()
                c0 = os.times()
                subprocess.run([a.riemesh, "adapt", src, "-o", out, "--hausd", repr(hausd), "--quiet"]
                               + (["--aniso"] if a.aniso else []), check=True)
                c1 = os.times()
                times.append(time.perf_counter() - t0)
                # CPU time of the child (user + system): robust to a loaded machine.
                cpus.append(c1.children_user - c0.children_user + c1.children_system - c0.children_system)
            d = json.loads(subprocess.run([a.riemesh, "distance", src, out, "--json"], check=True,
                                          capture_output=True, text=True).stdout)
            valid = subprocess.run([a.riemesh, "check", out], capture_output=True).returncode == 0
            ntri, qmin, qmean = quality(out)
            tin = quality(src)[0]
            row = dict(surface=name, hausd_fraction=frac, hausd=hausd, input_tris=tin, output_tris=ntri,
                       hausdorff=d["hausdorff"], ratio=d["hausdorff"] / hausd, q_min=qmin, q_mean=qmean,
                       valid=valid, wall_s=statistics.median(times), cpu_s=statistics.median(cpus))
            ref = ""
            if a.reference:
                row["reference_wall_s"] = statistics.median(ref_times)
                ref = "| %.3f | %.2f " % (row["reference_wall_s"], row["reference_wall_s"] / row["wall_s"])
            rows.append(row)
            mm = MMGS.get((name, frac))
            mms = "| %d | %.3f | %.3f | %.2f |" % (mm[0], mm[1], mm[2], mm[4]) if mm else "| | | | |"
            print("| %s | %g%% | %d | %d | %.3f | %.3f | %.3f | %s | %.3f | %.3f %s%s" % (
                name, 100 * frac, tin, ntri, row["ratio"], qmin, qmean, "yes" if valid else "NO",
                row["wall_s"], row["cpu_s"], ref, mms))
            sys.stdout.flush()
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
