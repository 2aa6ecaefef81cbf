#!/usr/bin/env python3
"""Chapter 18's chart data: RMSE against render time of three methods on two scenes (see
charts.sh). usage: methods_chart.py RT ROOT DATA_DIR CHARTS_DIR ROUNDS"""
import os
import re
import subprocess
import sys

rt, root, data, charts, rounds = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5])
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from images import rmse  # noqa: E402

SIZE = "96x96"
source = open(os.path.join(root, "scenes", "chapter16-photon-mapping.lua")).read()
assert "gr.photons{indirect = true}" in source
# Photons only where asked (the command line's --photons turns them on).
base = source.replace("gr.photons{indirect = true}\n", "")
no_balls = re.sub(r"\nlocal ball = .*?root:add_child\(mirror\)\n", "\n", base, flags=re.S)
assert no_balls != base
scenes = {"box": no_balls, "balls": base}
for name, text in scenes.items():
    with open(os.path.join(data, name + ".lua"), "w") as f:
        f.write(text)
    with open(os.path.join(data, name + "-photons.lua"), "w") as f:
        f.write("gr.photons{indirect = true}\n" + text)


def render(scene, out, args):
    """Render; return the render phase's seconds from --stats."""
    p = subprocess.run([rt, "--quiet", "--stats", "--size", SIZE, "--output", out] + args +
                       [os.path.join(data, scene + ".lua")], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"methods_chart: {rt} failed: {p.stderr}")
    m = re.search(r"render ([0-9.]+) s", p.stderr)
    return float(m.group(1))



# The references.
print("chapter 18 charts: references", file=sys.stderr)
render("box", f"{data}/ref-box.png", ["--integrator=path", "--spp", "4096", "--seed", "99"])
render("balls-photons", f"{data}/ref-balls.png",
       ["--photons", "200000", "--photon-passes", "256", "--seed", "99"])
# The series: (scene, method label, base args, effort option, efforts).
series = []
for scene in ("box", "balls"):
    series += [(scene, "path tracing", scene, ["--integrator=path"], "--spp", [1, 4, 16, 64, 256]),
               (scene, "photon mapping", scene + "-photons", [], "--photon-passes",
                [1, 4, 16, 64]),
               (scene, "Whitted + ambient", scene, [], "--spp", [1, 4, 16, 64])]
best, err = {}, {}
for r in range(rounds):
    print(f"chapter 18 charts: round {r + 1} of {rounds}", file=sys.stderr)
    for scene, label, lua, args, option, efforts in series:
        for n in efforts:
            out = f"{data}/img.png"
            t = render(lua, out, args + [option, str(n), "--seed", "1"])
            key = (scene, label, n)
            best[key] = min(best.get(key, t), t)
            if r == 0:
                err[key] = rmse(out, f"{data}/ref-{scene}.png")
with open(f"{data}/methods.dat", "w") as f:
    for scene, label, lua, args, option, efforts in series:
        f.write(f"# {scene}: {label}\n")
        for n in efforts:
            f.write(f"{n} {best[(scene, label, n)]:.4f} {err[(scene, label, n)]:.5f}\n")
        f.write("\n\n")
with open(f"{charts}/ch18-methods.txt", "w") as f:
    f.write("| scene | method | effort | render s | RMSE |\n|---|---|---:|---:|---:|\n")
    for scene, label, lua, args, option, efforts in series:
        for n in efforts:
            what = f"{n} {'paths a pixel' if option == '--spp' and label.startswith('path') else ('passes' if 'photon' in label else 'rays a pixel')}"
            f.write(f"| {'box' if scene == 'box' else 'glass and mirror balls'} | {label} | {what} | "
                    f"{best[(scene, label, n)]:.3f} | {err[(scene, label, n)]:.4f} |\n")
last = lambda scene, label: err[max(((s, l, n) for (s, l, n) in err if s == scene and l == label),
                                    key=lambda k: k[2])]
with open(f"{charts}/ch18-finding.txt", "w") as f:
    f.write(
        f"In the box without balls, path tracing's RMSE against its 4096-path reference falls to "
        f"{last('box', 'path tracing'):.4f} at 256 paths a pixel and photon mapping's to "
        f"{last('box', 'photon mapping'):.4f} at 64 passes, while Whitted + ambient stays at "
        f"{last('box', 'Whitted + ambient'):.4f} however many rays it takes; with the glass and "
        f"mirror balls under the point light, path tracing stops at "
        f"{last('balls', 'path tracing'):.4f} (it never draws the caustics), where photon "
        f"mapping reaches {last('balls', 'photon mapping'):.4f}.\n")
print(open(f"{charts}/ch18-finding.txt").read(), file=sys.stderr)
