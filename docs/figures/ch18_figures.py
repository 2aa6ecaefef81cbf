#!/usr/bin/env python3
"""Chapter 18's figure (SVG, written next to this script): one path through a box lit by a
lamp in its ceiling, in the notation of chapters/18-path-tracing.md.

    python3 docs/figures/ch18_figures.py

ch18-path.svg   a cross-section of the box: the camera's ray reaches x_0 on the floor; there
                light sampling picks the point y on the lamp (a dashed shadow ray, with the
                distance r and the angle theta_l at the lamp that turn its area density into a
                density per steradian), and the BSDF draws the next direction to x_1 on the
                wall; from x_1 the BSDF's ray happens to hit the lamp, which light sampling
                could also have picked: MIS weighs the two. Russian roulette ends the path at
                x_2.

Everything is computed in 2D; the file only changes when this script does.
"""
from svgfig import (BLUE, DARK, FILL_GREY, FILL_ORANGE, FILL_RED, GRID, INK, ORANGE, RED,
                    Figure, Frame2D, add, mul)

W, H = 5.5, 5.0          # the box's inside
LAMP = (2.1, 3.4)        # the lamp's extent in x, in the ceiling


def path_figure(name):
    fig = Figure(1000, 520, "one path: light sampling and BSDF sampling at each vertex, weighed by MIS")
    F = Frame2D((100, 470), 80)
    # The box: floor, ceiling, back wall (right) in grey; the lamp in the ceiling.
    fig.rect(*F((0, 0)), *F((W, -0.15)), "none", FILL_GREY, 0)
    fig.rect(*F((0, H + 0.15)), *F((W, H)), "none", FILL_GREY, 0)
    fig.rect(*F((W, H + 0.15)), *F((W + 0.15, -0.15)), "none", FILL_RED, 0)
    fig.line(F((0, 0)), F((W, 0)), DARK, 2)
    fig.line(F((0, H)), F((W, H)), DARK, 2)
    fig.line(F((W, 0)), F((W, H)), RED, 2.5)
    fig.rect(*F((LAMP[0], H + 0.06)), *F((LAMP[1], H)), ORANGE, FILL_ORANGE, 2)
    fig.text(F((2.75, H + 0.3)), "lamp: L_e", size=14, fill=ORANGE)
    # The camera, outside the open front (left).
    eye = (-0.45, 2.6)
    x0 = (2.2, 0.0)
    x1 = (W, 2.1)
    y = (3.1, H)
    hit_lamp = (2.55, H)
    x2 = (4.3, 0.0)
    fig.dot(F(eye), INK, 5)
    fig.text(add(F(eye), (0, -12)), "camera", size=13)
    fig.arrow(F(eye), F(x0), INK, 2)
    # Vertex x0: a shadow ray to y (light sampling), the BSDF's ray to x1.
    fig.line(F(x0), F(y), ORANGE, 1.8, dash="6 4")
    fig.arrow(F(x0), F(x1), BLUE, 2)
    # Vertex x1: the BSDF's ray hits the lamp (MIS), a shadow ray too, and the path goes on.
    fig.arrow(F(x1), F(hit_lamp), BLUE, 2)
    fig.line(F(x1), F((3.3, H)), ORANGE, 1.8, dash="6 4")
    fig.arrow(F(x1), F(x2), BLUE, 2)
    for p, label, off in ((x0, "x_0", (0, 22)), (x1, "x_1", (22, 4)), (x2, "x_2", (0, 22))):
        fig.dot(F(p), INK, 5)
        fig.text(add(F(p), off), label, size=15)
    fig.dot(F(y), ORANGE, 5)
    fig.text(add(F(y), (14, 22)), "y", size=15, fill=ORANGE)
    # The lamp's normal at y (down), against which θ_l is measured.
    fig.line(F(y), F((y[0], H - 0.9)), GRID, 1.2, dash="3 3")
    fig.text(add(F(y), (-14, 50)), "θ_l", size=14, fill=ORANGE)
    mid = mul(add(x0, y), 0.5)
    fig.text(add(F(mid), (-16, 0)), "r", size=15, fill=ORANGE)
    # The legend.
    fig.line((600, 60), (640, 60), ORANGE, 1.8, dash="6 4")
    fig.text((650, 64), "light sampling: p_A(y) r² / cos θ_l", anchor="start",
             size=13)
    fig.line((600, 88), (640, 88), BLUE, 2, arrow=True)
    fig.text((650, 92), "BSDF sampling: p(ω) of the lobes", anchor="start", size=13)
    fig.text((600, 120), "BSDF ray on the lamp: p_b² / (p_b² + p_l²)",
             anchor="start", size=13)
    fig.text((600, 144), "x_2: Russian roulette ends the path", anchor="start", size=13)
    fig.write(name)


if __name__ == "__main__":
    path_figure("ch18-path.svg")
