"""Triage of `fuzz/open/burmester_points` (five38): each input, both frames,
against the exact points of the float task (tests/python/burmester_reference.py).

    cargo test -p burmester --test fuzz_corpus -- --ignored --nocapture \\
        open_findings > open.txt 2> open.err
    python fuzz/reference/triage_five.py open.txt open.err

For each input: the check's failing point (task sizes out, `M` the check's
`rounding_moves` estimate, how far off the other frame's nearest point is);
per frame the task's near-degeneracy (`ij@d`: poses i, j within d task
sizes, `da` their angles that far apart, `half` half a turn apart; `ijda`
two poses of nearly one angle; `far` coordinates over the size), the
library's count, the reference's (real, at infinity, imaginary parts of the
complex pairs over the size), every library point's distance to the nearest
exact real point and every exact real point's (within 1e4 task sizes) to the
nearest library point, in units of `size + d`.
"""
import ast, os, re, sys, math
import mpmath
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "python"))
from burmester_reference import reference  # noqa: E402

def size_c(poses):
    cx = sum(p[0] for p in poses) / 5
    cy = sum(p[1] for p in poses) / 5
    return max(((p[0]-cx)**2 + (p[1]-cy)**2) ** 0.5 for p in poses), (cx, cy)

def degen(poses):
    s, (cx, cy) = size_c(poses)
    out = []
    for i in range(5):
        for j in range(i+1, 5):
            d = math.hypot(poses[i][0]-poses[j][0], poses[i][1]-poses[j][1]) / s
            a = (poses[j][2]-poses[i][2]) % (2*math.pi)
            a = min(a, 2*math.pi - a)
            if d < 1e-6:
                tag = f"{i+1}{j+1}@{d:.0e}"
                if a < 1e-5:
                    tag += f" da{a:.0e}"
                elif abs(a - math.pi) < 1e-5:
                    tag += " half"
                out.append(tag)
            elif a < 1e-6:
                out.append(f"{i+1}{j+1}da{a:.0e}")
    far = max(max(abs(p[0]), abs(p[1])) for p in poses) / s
    if far > 1e3:
        out.append(f"far{far:.0e}")
    return ",".join(out) or "-"

def judge(poses, pts):
    s, (cx, cy) = size_c(poses)
    ref = reference(poses)
    if ref is None:
        return None
    common, inf = ref
    real, cplx = [], []
    for x, y in common:
        im = max(abs(mpmath.im(x)), abs(mpmath.im(y)))
        if im <= 1e-30 * (1 + abs(x) + abs(y)):
            real.append((float(mpmath.re(x)), float(mpmath.re(y)), mpmath.re(x), mpmath.re(y)))
        else:
            cplx.append(float(im) / s)
    lib = []
    for x, y in pts:
        d = math.hypot(x-cx, y-cy)
        off = min((float(mpmath.sqrt((rx-x)**2 + (ry-y)**2)) for _, _, rx, ry in real), default=float('inf'))
        lib.append((x, y, d/s, off/(s+d)))
    miss = []
    for fx, fy, rx, ry in real:
        d = math.hypot(fx-cx, fy-cy)
        if d > 1e4 * s:
            continue
        off = min((float(mpmath.sqrt((rx-x)**2 + (ry-y)**2)) for x, y in pts), default=float('inf'))
        miss.append((fx, fy, d/s, off/(s+d)))
    return dict(real=len(real), inf=inf, cplx=cplx, lib=lib, exact=miss)

lines = open(sys.argv[1]).read().splitlines()
err = open(sys.argv[2]).read()
msgs = [m for m in re.split(r"\nthread 'open_findings' \(\d+\) panicked at ", err)[1:]]
msgs = [m for m in msgs if 'lib.rs:2062' not in m.split('\n')[0] and 'curves' not in m[:0]]
cur = None
fails = []
recs = []
for i, line in enumerate(lines):
    if line.startswith("burmester_points: /"):
        name = line.split("burmester_points/")[-1].split()[0]
        cur = dict(name=name, fails=line.endswith("fails"), frames={})
        recs.append(cur)
    elif cur and (line.startswith("  task ") or line.startswith("  moved ")):
        nm, rest = line.strip().split(" ", 1)
        poses = ast.literal_eval(rest)
        ans = lines[i+1].strip()
        cur["frames"][nm] = (poses, ans)
# the burmester panics, in order of the failing inputs
bmsgs = [m for m in msgs if "not among" in m or "spread" in m or "off its line" in m or "count" in m.lower()]
fi = 0
for r in recs:
    if r["fails"]:
        r["msg"] = bmsgs[fi] if fi < len(bmsgs) else "?"
        fi += 1
print("messages", len(bmsgs), "fails", sum(r["fails"] for r in recs), file=sys.stderr)
for r in recs:
    print("==", r["name"], "fails" if r["fails"] else "passes")
    if r.get("msg"):
        m = re.search(r"^\S+\s*(.*?)\n(.*?)\(([^ ]+) task sizes away.*?rounding moves it ([^ ]+) of size \+ d; in the other frame (.*?), the nearest point ([^ ]+) of size \+ d off", r["msg"], re.S)
        if m:
            print(f"  fail: point {m.group(2).strip()} ({float(m.group(3)):.3g} sizes) M={float(m.group(4)):.2e} other-frame nearest {float(m.group(6)):.2e}")
        else:
            print("  fail msg:", r["msg"][:300].replace("\n", " "))
    for nm, (poses, ans) in r["frames"].items():
        print(f"  {nm}: degen {degen(poses)}")
        if not ans.startswith("points"):
            print(f"    library {ans[:150]}")
            pts = []
        else:
            pts = ast.literal_eval(ans.split(" sliders")[0][len("points "):])
            print(f"    library {len(pts)} pts, sliders {ans.split('sliders ')[1]}")
        try:
            j = judge(poses, pts)
        except Exception as e:
            print("    reference failed", repr(e)); continue
        if j is None:
            print("    reference: not isolated"); continue
        print(f"    ref {j['real']}r {j['inf']}inf cplx {['%.1e'%c for c in j['cplx']]}")
        print("    lib->exact " + "; ".join(f"({x:.6g},{y:.6g}) {d:.2g}sz off {o:.1e}" for x, y, d, o in j['lib']))
        print("    exact->lib " + "; ".join(f"({x:.6g},{y:.6g}) {d:.2g}sz off {o:.1e}" for x, y, d, o in j['exact']))
    sys.stdout.flush()
