#!/usr/bin/python3
"""Robustness audit of the riemesh CLI: every subcommand over the real files of ../shared/data and
over damaged copies (truncated, numbers replaced by nan / -1 / 1e308 / huge ids, keywords misspelt,
.sol files with a wrong count or a non-SPD or NaN tensor, empty files, directories, missing files,
unwritable outputs, contradicting options). Each run has a time limit.

A run is a finding when it exits 3 or by a signal, hangs, exits 2 with more or less than one line
"riemesh: error: ..." on stderr, fails without naming the damaged file, leaves an output (or a
temporary beside it) after failing, or accepts a NaN. Prints one line per finding and a summary;
exits 1 if there is a finding.

  bench/robust_cli.py [--riemesh build/riemesh] [--shared ../shared] [--timeout 60] [--quick]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ap = argparse.ArgumentParser()
here = os.path.dirname(os.path.abspath(__file__))
ap.add_argument("--riemesh", default=os.path.join(here, "..", "build", "riemesh"))
ap.add_argument("--shared", default=os.path.join(here, "..", "..", "shared"))
ap.add_argument("--timeout", type=float, default=60)
ap.add_argument("--quick", action="store_true", help="small files only (the ctest-sized subset)")
ap.add_argument("-v", "--verbose", action="store_true", help="print every run")
args = ap.parse_args()
R = os.path.abspath(args.riemesh)
D = os.path.join(os.path.abspath(args.shared), "data")
T = tempfile.mkdtemp(prefix="riemesh-robust-")

runs = 0
findings = []
by_class = {}


def note_class(cls, ok):
    n = by_class.setdefault(cls, [0, 0])
    n[0] += 1
    n[1] += 0 if ok else 1


def run(cls, argv, outputs=(), damaged=None, expect_fail=False, nan_input=False):
    """Runs riemesh ARGV; checks the exit code, stderr and outputs. `damaged` is the path of the
    damaged input that an error must name; `expect_fail`: exit 0 is a finding too."""
    global runs
    runs += 1
    for o in outputs:
        if os.path.isfile(o):
            os.remove(o)
    t0 = time.time()
    try:
        p = subprocess.run([R] + argv, capture_output=True, text=True, errors="replace",
                           timeout=args.timeout, cwd=T)
        code, out, err = p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        code, out, err = "timeout", "", ""
    dt = time.time() - t0
    problems = []
    lines = [l for l in err.splitlines() if l.strip()]
    if code == "timeout":
        problems.append(f"hang (> {args.timeout:.0f} s)")
    elif code < 0 or code > 3:
        problems.append(f"signal/abnormal exit {code}")
    elif code == 3:
        problems.append("exit 3")
    if code not in (0, "timeout"):
        if code == 2:
            err_lines = [l for l in lines if l.startswith("riemesh: error:")]
            if len(err_lines) != 1:
                problems.append(f"{len(err_lines)} error lines")
            if damaged and err_lines and os.path.basename(damaged) not in err_lines[0]:
                problems.append("error does not name the file")
        for o in outputs:
            if os.path.exists(o):
                problems.append(f"output {os.path.basename(o)} left behind")
    for o in outputs:
        d = os.path.dirname(o) or T
        if os.path.isdir(d):
            left = [f for f in os.listdir(d) if ".tmp-" in f]
            if left:
                problems.append(f"temporary {left[0]} left behind")
                for f in left:
                    os.remove(os.path.join(d, f))
    if code == 0 and expect_fail:
        problems.append("accepted (exit 0)")
    if code == 0 and nan_input:
        problems.append("accepted a NaN (exit 0)")
    note_class(cls, not problems)
    msg = lines[-1] if lines else ""
    shown = " ".join(a.replace(T + "/", "").replace(D + "/", "") for a in argv)
    if problems:
        findings.append(f"{cls}: riemesh {shown}: {'; '.join(problems)} [exit {code}] {msg[:200]}")
        print("FINDING", findings[-1], flush=True)
    elif args.verbose:
        print(f"ok [{code}, {dt:.1f}s] riemesh {shown}: {msg[:160]}", flush=True)
    return code


def tmp(name):
    return os.path.join(T, name)


def write(name, data):
    path = tmp(name)
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(path, mode) as f:
        f.write(data)
    return path


def read(path):
    with open(path, "rb") as f:
        return f.read()


# --- damage -------------------------------------------------------------------------------------

NUM = re.compile(rb"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def keyword_offset(data, kw):
    m = re.search(rb"(?m)^\s*" + kw + rb"\b", data)
    return m.end() if m else None


def nth_number_after(data, start, n):
    """Span of the n-th number token after `start` (0-based)."""
    for i, m in enumerate(NUM.finditer(data, start)):
        if i == n:
            return m.span()
    return None


def medit_damages(data):
    """(label, bytes) damaged copies of an ASCII Medit mesh."""
    out = []
    size = len(data)
    for frac in (0.0005, 0.1, 0.5, 0.9, 0.999):
        out.append((f"trunc{frac}", data[: int(size * frac)]))
    # Numbers: the vertex count, the first vertex's coordinate, an element's vertex id and ref, the
    # element count.
    elem_kw = None
    for kw in (rb"Tetrahedra", rb"Triangles", rb"Edges"):
        if keyword_offset(data, kw) is not None:
            elem_kw = kw
            break
    targets = []
    v = keyword_offset(data, rb"Vertices")
    if v is not None:
        targets += [("vcount", v, 0), ("coord", v, 1), ("vref", v, 3 if b"Dimension 2" in data else 4)]
    if elem_kw is not None:
        e = keyword_offset(data, elem_kw)
        targets += [("ecount", e, 0), ("eid", e, 1), ("eid2", e, 2)]
    for label, start, n in targets:
        span = nth_number_after(data, start, n)
        if not span:
            continue
        for rep in (b"nan", b"-1", b"1e308", b"99999999999", b"0", b"inf", b"1.5", b"x"):
            out.append((f"{label}={rep.decode()}", data[: span[0]] + rep + data[span[1]:]))
    for kw, bad in ((b"Vertices", b"Vertixes"), (b"Triangles", b"Triangels"),
                    (b"Dimension", b"Dimensoin"), (b"Tetrahedra", b"Tetraedra")):
        if kw in data:
            out.append((f"kw-{bad.decode()}", data.replace(kw, bad, 1)))
    out.append(("no-End", re.sub(rb"(?m)^\s*End\s*$", b"", data)))
    out.append(("dup-Vertices", data.replace(b"Vertices", b"Vertices\n0\nVertices", 1)))
    return out


def binary_damages(data):
    out = []
    size = len(data)
    for frac in (0.001, 0.01, 0.1, 0.5, 0.9, 0.999):
        out.append((f"trunc{frac}", data[: int(size * frac)]))
    for off in (4, 8, 12, 16, 20, 24, 32, 40, 48, 64, 100, size // 3):
        for b in (b"\xff\xff\xff\x7f", b"\x00\x00\x00\x00", b"\x00\x00\xf8\x7f"):
            out.append((f"flip{off}-{b.hex()}", data[:off] + b + data[off + 4:]))
    return out


def text_damages(data, keywords):
    out = []
    size = len(data)
    for frac in (0.001, 0.1, 0.5, 0.9, 0.999):
        out.append((f"trunc{frac}", data[: int(size * frac)]))
    for kw in keywords:
        k = data.find(kw)
        if k < 0:
            continue
        out.append((f"kw-{kw.decode()}", data.replace(kw, kw[:-1] + b"X", 1)))
        for n in (0, 1, 2, 4):
            span = nth_number_after(data, k + len(kw), n)
            if not span:
                continue
            for rep in (b"nan", b"-1", b"1e308", b"99999999999"):
                out.append((f"{kw.decode()}#{n}={rep.decode()}", data[: span[0]] + rep + data[span[1]:]))
    return out


def sol_damages(data):
    """Damaged copies of a .sol: wrong count, non-SPD, NaN, negative size, truncated, bad type."""
    out = []
    s = data.decode()
    m = re.search(r"SolAtVertices\s*\n\s*(\d+)\s*\n\s*(\d+)\s+(\d+)\s*\n", s)
    count, nfields, kind = int(m.group(1)), int(m.group(2)), int(m.group(3))
    head, body = s[: m.start(1)], s[m.end(3):]
    rows = body.strip("\n").split("\n")

    def with_row(i, row):
        rr = list(rows)
        rr[i] = row
        return (head + f"{count}\n{nfields} {kind}\n" + "\n".join(rr) + "\n").encode()

    out.append(("count-1", (head + f"{count - 1}\n{nfields} {kind}" + body).encode()))
    out.append(("count+1", (head + f"{count + 1}\n{nfields} {kind}" + body).encode()))
    out.append(("count-huge", (head + f"99999999999\n{nfields} {kind}" + body).encode()))
    out.append(("count-neg", (head + f"-3\n{nfields} {kind}" + body).encode()))
    out.append(("type-9", (head + f"{count}\n{nfields} 9" + body).encode()))
    out.append(("nfields-0", (head + f"{count}\n0 {kind}" + body).encode()))
    if kind == 3:
        out.append(("nonspd", with_row(5, "1 2 1")))
        out.append(("zero", with_row(5, "0 0 0")))
        out.append(("negdef", with_row(0, "-1 0 -1")))
        out.append(("nan", with_row(5, "nan 0 1")))
        out.append(("inf", with_row(5, "inf 0 1")))
        out.append(("huge", with_row(5, "1e308 0 1e308")))
        out.append(("tiny", with_row(5, "1e-308 0 1e-308")))
    else:
        out.append(("nan", with_row(5, "nan")))
        out.append(("neg", with_row(5, "-1")))
        out.append(("zero", with_row(5, "0")))
        out.append(("inf", with_row(5, "inf")))
    out.append(("words", with_row(3, "abc")))
    for frac in (0.01, 0.5, 0.99):
        out.append((f"trunc{frac}", data[: int(len(data) * frac)]))
    return out


# --- the runs -----------------------------------------------------------------------------------

def mesh_commands(path, dim_kind, cls, damaged=None, nan=False):
    """Every read-only and writing command that takes this mesh, by kind (2d, surf, vol)."""
    ext = os.path.splitext(path)[1]
    out_mesh, out_b, out_svg = tmp("o.mesh"), tmp("o.meshb"), tmp("o.svg")
    out_msh, out_vtu = tmp("o.msh"), tmp("o.vtu")
    kw = dict(damaged=damaged, nan_input=nan)
    run(cls, ["check", path], **kw)
    run(cls, ["stats", path, "--json"], **kw)
    run(cls, ["convert", path, out_b], [out_b], **kw)
    run(cls, ["convert", path, out_msh, "--binary", "--hilbert"], [out_msh], **kw)
    run(cls, ["convert", path, out_vtu], [out_vtu], **kw)
    run(cls, ["render", path, "-o", out_svg], [out_svg], **kw)
    if dim_kind == "2d":
        run(cls, ["convert", path, out_mesh, "--boundary"], [out_mesh], **kw)
        run(cls, ["adapt", path, "--hsiz", "0.2", "-o", out_mesh, "-q", "--passes", "3"],
            [out_mesh], **kw)
        run(cls, ["mesh", path, "-o", out_mesh, "-q", "--passes", "2"], [out_mesh], **kw)
    elif dim_kind == "surf":
        run(cls, ["distance", path, path, "--samples", "1"], **kw)
        run(cls, ["mesh", path, "-o", out_mesh, "-q", "--passes", "1"], [out_mesh], **kw)
        run(cls, ["metric", "geometric", path, "--hausd", "0.01", "-o", tmp("g.sol")],
            [tmp("g.sol")], **kw)
    elif dim_kind == "vol":
        run(cls, ["adapt", path, "--optim", "--nosurf", "-o", out_mesh, "-q", "--passes", "1"],
            [out_mesh], **kw)


def kind_of(path):
    data = read(path)[:4000]
    if b"Tetrahedra" in read(path) or "vol" in path:
        return "vol"
    if re.search(rb"Dimension\s+3", data) or "surf" in path:
        return "surf"
    return "2d"


real = {
    "2d": [f"{D}/2d/aile.mesh", f"{D}/formats/lshape.mesh", f"{D}/2d/naca0012.mesh",
           f"{D}/2d/lac-leman.mesh", f"{D}/dialects/aile_freefem.mesh", f"{D}/dialects/t4_gmsh2d.mesh",
           f"{D}/formats/naca0012_v22.msh", f"{D}/formats/naca0012.vtu"],
    "surf": [f"{D}/surf/rotor.mesh", f"{D}/surf/bunny.mesh", f"{D}/surf/elephant.mesh",
             f"{D}/surf/fandisk.mesh"],
    "vol": [f"{D}/dialects/dodecaedre01.mesh", f"{D}/dialects/cgal_sphere.mesh",
            f"{D}/vol/bunny_vol.mesh", f"{D}/vol/screw_vol.mesh", f"{D}/formats/bunny_vol.meshb",
            f"{D}/formats/bunny_vol.msh", f"{D}/formats/bunny_vol_v22.msh"],
}
if args.quick:
    real = {"2d": [f"{D}/2d/aile.mesh"], "surf": [], "vol": [f"{D}/dialects/dodecaedre01.mesh"]}

print(f"riemesh robustness audit: {R}, scratch {T}", flush=True)

# 1. Real files: everything must succeed or refuse cleanly.
for kind, files in real.items():
    for f in files:
        if f.endswith(".vtu"):  # read-only format for riemesh? still must refuse cleanly
            pass
        mesh_commands(f, kind, f"real-{kind}")
lshape, lsol, lmet = f"{D}/formats/lshape.mesh", f"{D}/formats/lshape.sol", f"{D}/formats/lshape_metric.sol"
run("real-2d", ["adapt", lshape, "--metric", lmet, "-o", tmp("o.mesh"), "-q", "--passes", "3"])
run("real-2d", ["adapt", lshape, "--field", lsol, "--complexity", "500", "-o", tmp("o.mesh"), "-q",
                "--passes", "3"])
run("real-2d", ["stats", lshape, "--metric", lmet, "--json"])
run("real-2d", ["render", lshape, "--metric", lmet, "--color", "size", "-o", tmp("o.svg")])
run("real-2d", ["transfer", lshape, lsol, f"{D}/2d/aile.mesh", "-o", tmp("t.sol")])
run("real-2d", ["transfer", lshape, lsol, lshape, "-o", tmp("t.sol")])
run("real-2d", ["metric", "hessian", lshape, lsol, "--complexity", "800", "-o", tmp("h.sol")])
run("real-2d", ["metric", "combine", lmet, lmet, "--mesh", lshape, "-o", tmp("c.sol")])

# 2. Damaged meshes.
damage_sources = [f"{D}/2d/aile.mesh", f"{D}/formats/lshape.mesh", f"{D}/dialects/dodecaedre01.mesh",
                  f"{D}/surf/rotor.mesh"]
if args.quick:
    damage_sources = [f"{D}/2d/aile.mesh", f"{D}/dialects/dodecaedre01.mesh"]
for src in damage_sources:
    kind = kind_of(src)
    base = os.path.splitext(os.path.basename(src))[0]
    for label, data in medit_damages(read(src)):
        name = f"{base}.{re.sub(r'[^A-Za-z0-9.=+-]', '_', label)}.mesh"
        p = write(name, data)
        nan = "nan" in label or "inf" in label
        if args.quick:
            run(f"damaged-{kind}", ["check", p], damaged=p, nan_input=nan)
            run(f"damaged-{kind}", ["convert", p, tmp("o.meshb")], [tmp("o.meshb")], damaged=p,
                nan_input=nan)
        else:
            mesh_commands(p, kind, f"damaged-{kind}", damaged=p, nan=nan)

if not args.quick:
    for src, kw in ((f"{D}/formats/bunny_vol.meshb", None), (f"{D}/formats/bunny_vol.msh", None),
                    (f"{D}/formats/naca0012_v22.msh", [b"$Nodes", b"$Elements", b"$MeshFormat"]),
                    (f"{D}/formats/naca0012.vtu", [b"NumberOfPoints", b"connectivity", b"offsets"])):
        data = read(src)
        base, ext = os.path.splitext(os.path.basename(src))
        dmg = binary_damages(data) if kw is None else text_damages(data, kw)
        for label, d in dmg:
            p = write(f"{base}.{re.sub(r'[^A-Za-z0-9.=+-]', '_', label)}{ext}", d)
            run(f"damaged-{ext[1:]}", ["check", p], damaged=p)
            run(f"damaged-{ext[1:]}", ["stats", p], damaged=p)
            run(f"damaged-{ext[1:]}", ["convert", p, tmp("o.mesh")], [tmp("o.mesh")], damaged=p)

# 3. Damaged .sol files with their mesh.
for label, data in sol_damages(read(lmet)):
    p = write(f"lshape_metric.{label}.sol", data)
    nan = label in ("nan", "inf")
    bad = label not in ("huge", "tiny")
    o = tmp("o.mesh")
    run("damaged-sol", ["adapt", lshape, "--metric", p, "-o", o, "-q", "--passes", "2"], [o],
        damaged=p, expect_fail=bad, nan_input=nan)
    run("damaged-sol", ["stats", lshape, "--metric", p], damaged=p, expect_fail=bad)
    if not args.quick:
        run("damaged-sol", ["render", lshape, "--metric", p, "-o", tmp("o.svg")], [tmp("o.svg")],
            damaged=p, expect_fail=bad)
        run("damaged-sol", ["metric", "combine", p, lmet, "--mesh", lshape, "-o", tmp("c.sol")],
            [tmp("c.sol")], damaged=p, expect_fail=bad)
for label, data in sol_damages(read(lsol)):
    p = write(f"lshape.{label}.sol", data)
    nan = label in ("nan", "inf")
    o = tmp("o.sol")
    run("damaged-sol", ["metric", "hessian", lshape, p, "--complexity", "500", "-o", o], [o],
        damaged=p, nan_input=nan)
    if not args.quick:
        run("damaged-sol", ["transfer", lshape, p, f"{D}/2d/aile.mesh", "-o", o], [o], damaged=p,
            nan_input=nan)
        run("damaged-sol", ["adapt", lshape, "--field", p, "--complexity", "300", "-o",
                            tmp("o.mesh"), "-q", "--passes", "2"], [tmp("o.mesh"), tmp("o.sol")],
            damaged=p, nan_input=nan)

# 4. Empty files, directories, missing files, unwritable outputs.
empty = write("empty.mesh", b"")
empty_sol = write("empty.sol", b"")
os.makedirs(tmp("dir.mesh"), exist_ok=True)
# A folder that cannot be created into: below a regular file (read-only folders do not stop root).
ro = os.path.join(empty, "sub")
aile = f"{D}/2d/aile.mesh"
for p in (empty, tmp("dir.mesh"), tmp("missing.mesh"), "/dev/null"):
    run("paths", ["check", p], damaged=p, expect_fail=True)
    run("paths", ["stats", p], damaged=p, expect_fail=True)
    run("paths", ["convert", p, tmp("o.mesh")], [tmp("o.mesh")], damaged=p, expect_fail=True)
    run("paths", ["adapt", p, "--hsiz", "0.1", "-o", tmp("o.mesh")], [tmp("o.mesh")], damaged=p,
        expect_fail=True)
    run("paths", ["mesh", p, "-o", tmp("o.mesh")], [tmp("o.mesh")], damaged=p, expect_fail=True)
for p in (empty_sol, tmp("dir.mesh"), tmp("missing.sol")):
    run("paths", ["adapt", lshape, "--metric", p, "-o", tmp("o.mesh")], [tmp("o.mesh")], damaged=p,
        expect_fail=True)
    run("paths", ["stats", lshape, "--metric", p], damaged=p, expect_fail=True)
    run("paths", ["metric", "hessian", lshape, p, "--complexity", "100", "-o", tmp("h.sol")],
        damaged=p, expect_fail=True)
    run("paths", ["transfer", lshape, p, lshape, "-o", tmp("t.sol")], damaged=p, expect_fail=True)
for o in (f"{ro}/o", "/nonexistent/o", tmp("dir")):
    for ext in (".mesh", ".meshb", ".msh", ".vtu", ".sol", ".svg", ".png"):
        os.makedirs(tmp("dir") + ext, exist_ok=True)  # an output name taken by a folder
    for ext in (".mesh", ".meshb", ".msh", ".vtu"):
        run("unwritable", ["convert", aile, o + ext], damaged=o + ext, expect_fail=True)
    run("unwritable", ["adapt", aile, "--hsiz", "0.2", "-o", o + ".mesh", "-q"], damaged=o + ".mesh",
        expect_fail=True)
    run("unwritable", ["adapt", lshape, "--metric", lmet, "-o", tmp("o.mesh"), "--out-metric",
                       o + ".sol", "-q"], [tmp("o.mesh")], damaged=o + ".sol", expect_fail=True)
    run("unwritable", ["render", aile, "-o", o + ".svg"], damaged=o + ".svg", expect_fail=True)
    run("unwritable", ["render", aile, "-o", o + ".png"], damaged=o + ".png", expect_fail=True)
    run("unwritable", ["stats", aile, "--plot", o + ".png"], damaged=o + ".png", expect_fail=True)
    run("unwritable", ["mesh", aile, "-o", o + ".mesh", "-q"], damaged=o + ".mesh", expect_fail=True)
    run("unwritable", ["metric", "hessian", lshape, lsol, "--complexity", "100", "-o", o + ".sol"],
        damaged=o + ".sol", expect_fail=True)
    run("unwritable", ["transfer", lshape, lsol, lshape, "-o", o + ".sol"], damaged=o + ".sol",
        expect_fail=True)
    run("unwritable", ["metric", "geometric", f"{D}/surf/rotor.mesh", "--hausd", "0.01", "-o",
                       o + ".sol"], damaged=o + ".sol", expect_fail=True)

# 5. Contradicting or out-of-range options.
o = tmp("o.mesh")
bad_options = [
    ["adapt", aile, "--hmin", "0.5", "--hmax", "0.1", "-o", o],
    ["adapt", lshape, "--hsiz", "0.1", "--metric", lmet, "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--hausd", "-1", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--hausd", "0", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--passes", "0", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--passes", "-3", "-o", o],
    ["adapt", aile, "--hsiz", "0", "-o", o],
    ["adapt", aile, "--hsiz", "-0.1", "-o", o],
    ["adapt", aile, "--hsiz", "nan", "-o", o],
    ["adapt", aile, "--hsiz", "inf", "-o", o],
    ["adapt", aile, "--hsiz", "1e-300", "-o", o],
    ["adapt", aile, "--hmax", "nan", "-o", o],
    ["adapt", aile, "--hmin", "-1", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--hgrad", "-2", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--hgrad", "0.5", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--hgrad", "nan", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--angle", "-5", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--angle", "400", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--interp", "bogus", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "--approach", "-1", "-o", o],
    ["adapt", aile, "--optim", "--hsiz", "0.1", "-o", o],
    ["adapt", aile, "--hsiz", "0.1", "-o", o, "-v", "-5"],
    ["adapt", aile, "--hsiz", "0.1", "-o", tmp("o.txt")],
    ["adapt", aile, "--hsiz", "0.1"],
    ["adapt", lshape, "--field", lsol, "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "0", "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "-5", "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "nan", "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "1e12", "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "100", "--metric", lmet, "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "100", "--norm", "0.5", "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "100", "--norm", "abc", "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "100", "--aniso-max", "0.5", "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "100", "--recovery", "x", "-o", o],
    ["adapt", lshape, "--field", lsol, "--complexity", "100", "--field-name", "9", "-o", o],
    ["adapt", lshape, "--metric", lmet, "--fields", lmet, "-o", o],
    ["adapt", lshape, "--metric", lmet, "--fields", f"{D}/formats/lshape.sol", "-o", o,
     "--out-fields", o],
    ["adapt", f"{D}/surf/rotor.mesh", "--hausd", "-0.1", "-o", o],
    ["adapt", f"{D}/surf/rotor.mesh", "--hmin", "1", "--hmax", "0.1", "-o", o],
    ["mesh", aile, "--hsiz", "-1", "-o", o],
    ["mesh", aile, "--hsiz", "0", "-o", o],
    ["mesh", aile, "--hsiz", "nan", "-o", o],
    ["mesh", aile, "--hmin", "1", "--hmax", "0.1", "-o", o],
    ["mesh", aile, "--hausd", "-1", "-o", o],
    ["mesh", aile, "--passes", "-1", "-o", o],
    ["mesh", aile, "--hole", "abc", "-o", o],
    ["mesh", aile, "--hole", "nan,nan", "-o", o],
    ["mesh", aile, "--hole", "1e308,1e308", "-o", o],
    ["mesh", aile, "--hsiz", "0.1", "--metric", lmet, "-o", o],
    ["mesh", lshape, "--metric", lmet, "--hgrad", "-1", "-o", o],
    ["convert", aile, tmp("o.xyz")],
    ["convert", aile, aile.replace(".mesh", ".xyz")],
    ["stats", aile, "--plot", tmp("o.bmp")],
    ["stats", aile, "--width", "10"],
    ["render", aile, "-o", tmp("o.bmp")],
    ["render", aile, "-o", tmp("o.svg"), "--width", "0"],
    ["render", aile, "-o", tmp("o.svg"), "--view", "w"],
    ["render", aile, "-o", tmp("o.svg"), "--color", "size"],
    ["distance", aile, f"{D}/surf/rotor.mesh"],
    ["distance", f"{D}/surf/rotor.mesh", f"{D}/surf/rotor.mesh", "--samples", "0"],
    ["distance", f"{D}/surf/rotor.mesh", f"{D}/surf/rotor.mesh", "--spacing", "nan"],
    ["distance", f"{D}/surf/rotor.mesh", f"{D}/surf/rotor.mesh", "--spacing", "1e-300"],
    ["transfer", lshape, lsol, f"{D}/surf/rotor.mesh", "-o", tmp("t.sol")],
    ["transfer", lshape, lsol, lshape, "-o", tmp("t.sol"), "--p0"],
    ["transfer", lshape, lmet, f"{D}/2d/naca0012.mesh", "-o", tmp("t.sol")],
    ["transfer", lshape, f"{D}/formats/lshape.sol", aile],
    ["metric", "hessian", lshape, lsol, "-o", tmp("h.sol")],
    ["metric", "hessian", lshape, lsol, "--complexity", "100", "--tolerance", "0.1", "-o", tmp("h.sol")],
    ["metric", "hessian", lshape, lsol, "--complexity", "100", "--hmin", "1", "--hmax", "0.1",
     "-o", tmp("h.sol")],
    ["metric", "hessian", lshape, lsol, "--norm", "inf", "--tolerance", "-1", "-o", tmp("h.sol")],
    ["metric", "hessian", lshape, lsol, "--norm", "inf", "--tolerance", "nan", "-o", tmp("h.sol")],
    ["metric", "hessian", lshape, lsol, "--complexity", "100", "--hgrad", "-1", "-o", tmp("h.sol")],
    ["metric", "hessian", aile, lsol, "--complexity", "100", "-o", tmp("h.sol")],
    ["metric", "hessian", lshape, lmet, "--complexity", "100", "-o", tmp("h.sol")],
    ["metric", "combine", lmet, "--mesh", lshape, "-o", tmp("c.sol")],
    ["metric", "combine", lmet, lmet, "--mesh", aile, "-o", tmp("c.sol")],
    ["metric", "combine", lmet, lsol, "--mesh", lshape, "-o", tmp("c.sol")],
    ["metric", "combine", lsol, lsol, "--mode", "lp", "--complexity", "-1", "--mesh", lshape,
     "-o", tmp("c1.sol") + "," + tmp("c2.sol")],
    ["metric", "combine", lsol, lsol, "--mode", "lp", "--complexity", "100", "--meshes", lshape,
     "-o", tmp("c1.sol")],
    ["metric", "combine", lsol, lsol, "--mode", "lp", "--complexity", "100", "--intervals", "0",
     "--meshes", lshape, "-o", tmp("c1.sol")],
    ["metric", "combine", lsol, lsol, "--mode", "xx", "--mesh", lshape, "-o", tmp("c.sol")],
    ["metric", "geometric", f"{D}/surf/rotor.mesh", "--hausd", "-1", "-o", tmp("g.sol")],
    ["metric", "geometric", f"{D}/surf/rotor.mesh", "--hausd", "nan", "-o", tmp("g.sol")],
    ["metric", "geometric", aile, "--hausd", "0.01", "-o", tmp("g.sol")],
    ["metric", "calc", "interp", "--t", "nan", "1,0,1", "2,0,2"],
    ["metric", "calc", "interp", "--t", "2", "1,0,1", "2,0,2"],
    ["metric", "calc", "interp", "1,0,1", "2,0,2,0,0,2"],
    ["metric", "calc", "intersect", "1,2,1", "2,0,2"],
    ["metric", "calc", "intersect", "nan,0,1", "2,0,2"],
    ["metric", "calc", "intersect", "1e308,0,1e308", "1e-308,0,1e-308"],
    ["metric", "calc", "element", "0,0", "1,0", "2,0"],
    ["metric", "calc", "element", "0,0", "1,0", "nan,1"],
    ["metric", "calc", "element", "0,0", "1e308,0", "0,1e308"],
    ["metric", "calc", "length", "--metric", "1,0,1", "nan,1"],
    ["metric", "calc", "length", "--metric", "-1,0,1", "1,1"],
    ["loop", "--complexities", "100,50"],
    ["loop", "--complexities", "0"],
    ["loop", "--complexities", "abc"],
    ["loop", "--norm", "0.5", "--complexities", "100"],
    ["loop", "--hmin", "1", "--hmax", "0.1", "--complexities", "100"],
    ["loop", "--iterations", "0", "--complexities", "100"],
    ["loop", "--function", "nope", "--complexities", "100"],
    ["unsteady", "--intervals", "0", "--complexities", "100"],
    ["unsteady", "--samples", "1", "--complexities", "100"],
    ["unsteady", "--complexities", "-100"],
    ["unsteady", "--combine", "zz", "--complexities", "100"],
    ["unsteady", "--hmin", "1", "--hmax", "0.1", "--complexities", "100"],
]
for argv in bad_options:
    outs = [a for a in argv if a.startswith(T) and os.path.splitext(a)[1] in
            (".mesh", ".sol", ".svg", ".png", ".xyz", ".bmp")]
    run("options", argv, outs)

print(f"\n{runs} runs, {len(findings)} findings")
for cls, (n, bad) in sorted(by_class.items()):
    print(f"  {cls:16s} {n:5d} runs, {bad:3d} findings")
shutil.rmtree(T, ignore_errors=True)
sys.exit(1 if findings else 0)
