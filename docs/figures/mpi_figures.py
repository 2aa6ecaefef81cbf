#!/usr/bin/env python3
"""The figure of the page "Rendering on many machines" (docs/many-machines.md), an SVG written
next to this script:

    python3 docs/figures/mpi_figures.py

mpi-leasing.svg   top: rank 0 leases batches of tiles (positions in render order) from one queue
                  to every rank, itself included; each finished lease comes back as floats, goes
                  into the film and is appended to the journal; the image is written once, by
                  rank 0. Bottom: a photon pass's chunks split into contiguous shares, one per
                  rank, joined in rank order, so every rank holds the map one process traces.
"""
from svgfig import BLUE, DARK, FILL_BLUE, FILL_GREY, FILL_ORANGE, GREEN, INK, ORANGE, RED, Figure

RANK_FILL = ["#e3ebf8", "#fdf0d9", "#e2f3e6", "#fbe3e3"]
RANK_INK = [BLUE, ORANGE, GREEN, RED]


def leasing_figure(name):
    fig = Figure(860, 470, "MPI tile leasing, the journal, and a photon pass's shares")
    # Rank 0: the queue, the film, the journal and the image.
    fig.rect(20, 20, 330, 250, stroke=BLUE, fill=FILL_BLUE)
    fig.text((175, 44), "*rank 0*", size=15)
    fig.text((30, 72), "lease queue (render order, shrinking", anchor="start", size=12)
    fig.text((30, 88), "batches: a quarter of a fair share)", anchor="start", size=12)
    # The queue: tiles already leased shaded by rank, the rest plain.
    owners = [0, 0, 1, 1, 2, 2, 3, 3, 0, 1, 2, 3, 1, 0, 2, 3, None, None, None, None]
    for k, owner in enumerate(owners):
        x = 30 + k * 14.5
        fig.rect(x, 98, x + 12, 112, stroke=DARK, width=0.8,
                 fill=RANK_FILL[owner] if owner is not None else "white")
    fig.text((30, 136), "film: the image's floats; each tile", anchor="start", size=12)
    fig.text((30, 152), "placed as it arrives, from any rank", anchor="start", size=12)
    for y in range(4):
        for x in range(6):
            owner = (x * 7 + y * 3) % 4
            fig.rect(30 + x * 22, 160 + y * 18, 50 + x * 22, 176 + y * 18, stroke=DARK,
                     width=0.8, fill=RANK_FILL[owner])
    fig.rect(180, 162, 320, 198, stroke=DARK, fill="white")
    fig.text((250, 178), "out.png.journal", size=12)
    fig.text((250, 193), "append, flush each tile", size=11)
    fig.arrow((162, 190), (178, 182), stroke=DARK, width=1.5)
    fig.rect(180, 206, 320, 238, stroke=DARK, fill="white")
    fig.text((250, 220), "out.png", size=12)
    fig.text((250, 234), "written once, atomically", size=11)
    fig.arrow((162, 225), (178, 222), stroke=DARK, width=1.5)
    # Workers.
    for r in range(1, 4):
        y = 20 + (r - 1) * 80
        fig.rect(560, y, 840, y + 66, stroke=RANK_INK[r], fill=RANK_FILL[r])
        fig.text((700, y + 22), f"*rank {r}*: parses the scene itself,", size=13)
        fig.text((700, y + 40), "holds 3 leases, renders each with", size=12)
        fig.text((700, y + 56), "its OpenMP threads, sends it back", size=12)
        fig.arrow((332, 60 + (r - 1) * 50), (558, y + 18), stroke=RANK_INK[r], width=1.6)
        fig.arrow((558, y + 48), (332, 80 + (r - 1) * 50), stroke=RANK_INK[r], width=1.6,
                  dash="5,3")
    fig.text((445, 40), "lease: tile positions", size=12)
    fig.text((445, 248), "dashed: the finished lease's floats,", size=12)
    fig.text((445, 263), "sent without waiting (Isend)", size=12)
    # The photon pass.
    y0 = 300
    fig.text((20, y0 - 16), "*a photon pass* (chapter 16): chunks of 1024 photons, each rank "
             "traces a contiguous share;", anchor="start", size=13)
    fig.text((20, y0), "the shares, joined in rank order (Allgatherv), are the chunks in order",
             anchor="start", size=13)
    chunks = 24
    for c in range(chunks):
        rank = c * 4 // chunks
        x = 20 + c * 34
        fig.rect(x, y0 + 20, x + 30, y0 + 46, stroke=RANK_INK[rank], fill=RANK_FILL[rank])
        fig.text((x + 15, y0 + 38), str(c), size=11)
    for rank in range(4):
        x = 20 + rank * 6 * 34
        fig.text((x + 100, y0 + 66), f"rank {rank} traces these", size=12, fill=RANK_INK[rank])
    fig.text((20, y0 + 104), "every rank, after the join:", anchor="start", size=13)
    for c in range(chunks):
        rank = c * 4 // chunks
        x = 210 + c * 26
        fig.rect(x, y0 + 88, x + 24, y0 + 110, stroke=RANK_INK[rank], fill=RANK_FILL[rank])
    fig.text((20, y0 + 146), "the same photons, in the same order, as one process traces: the "
             "grid, the gathers and so every pixel are bit-identical", anchor="start", size=13,
             fill=INK)
    return fig.write(name)


if __name__ == "__main__":
    print(leasing_figure("mpi-leasing.svg"))
