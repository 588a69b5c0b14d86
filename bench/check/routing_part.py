#!/usr/bin/env python3
"""A routing-style G-code program of any length, for timing `ncinterp check` on long parts.

The idea: a sheet of small parts nested in a grid, cut as a CAM post writes a router job
(Fusion 360 / FreeCAD style: G0 at safe height, plunge, cut, retract): each part is a
rounded rectangle with a bore in the middle, the bore first, every outline at `--passes`
depths. At `--tol 0.01` each part gives about 69 tape blocks per pass (the arcs become
chords, with the traverses), so `--blocks N` picks the number of parts for about N blocks.

    python3 bench/check/routing_part.py --blocks 60000 > routing.nc
    build/ncinterp tape routing.nc -o routing.tape
    build/ncinterp check routing.tape --contour routing.nc
"""
import argparse
import math

BLOCKS_PER_PART_PASS = 69  # measured at tol 0.01 mm with the defaults below


def part(out, x0, y0, w, h, r, bore, depths):
    cx, cy = x0 + w / 2, y0 + h / 2
    # The bore: a full circle, climb-cut clockwise, at every depth.
    out.append(f"G0 X{cx + bore:.3f} Y{cy:.3f}")
    for z in depths:
        out.append(f"G1 Z{z:.3f} F300")
        out.append(f"G2 X{cx + bore:.3f} Y{cy:.3f} I{-bore:.3f} J0 F1000")
    out.append("G0 Z5")
    # The outline: counter-clockwise from the middle of the bottom edge.
    out.append(f"G0 X{x0 + w / 2:.3f} Y{y0:.3f}")
    for z in depths:
        out.append(f"G1 Z{z:.3f} F300")
        out.append(f"G1 X{x0 + w - r:.3f} F1000")
        out.append(f"G3 X{x0 + w:.3f} Y{y0 + r:.3f} I0 J{r:.3f}")
        out.append(f"G1 Y{y0 + h - r:.3f}")
        out.append(f"G3 X{x0 + w - r:.3f} Y{y0 + h:.3f} I{-r:.3f} J0")
        out.append(f"G1 X{x0 + r:.3f}")
        out.append(f"G3 X{x0:.3f} Y{y0 + h - r:.3f} I0 J{-r:.3f}")
        out.append(f"G1 Y{y0 + r:.3f}")
        out.append(f"G3 X{x0 + r:.3f} Y{y0:.3f} I{r:.3f} J0")
        out.append(f"G1 X{x0 + w / 2:.3f}")
    out.append("G0 Z5")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--blocks", type=int, default=60000, help="about this many tape blocks")
    ap.add_argument("--passes", type=int, default=2, help="depth passes per part")
    args = ap.parse_args()
    depths = [-(k + 1) * 1.0 for k in range(args.passes)]
    parts = max(1, round(args.blocks / (BLOCKS_PER_PART_PASS * args.passes)))
    columns = max(1, int(math.sqrt(parts * 12 / 20)))
    out = ["(routing-style part for ncinterp's check benchmark: %d parts, %d passes)" % (parts, args.passes),
           "G21 G90 G17", "M3 S18000", "G0 Z5"]
    for k in range(parts):
        row, col = divmod(k, columns)
        part(out, col * 26.0, row * 18.0, 20.0, 12.0, 3.0, 3.0, depths)
    out += ["M5", "G0 X0 Y0", "M30"]
    print("\n".join(out))


if __name__ == "__main__":
    main()
