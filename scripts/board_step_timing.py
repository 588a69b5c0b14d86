#!/usr/bin/env python3
"""Step pulse timing on the board's PMOD pins, measured from a board-sim VCD.

Usage: scripts/board_step_timing.py WAVES.vcd [--clock-hz 12e6]

Reads board_core's step_x_o/dir_x_o/step_y_o/dir_y_o (the stretched outputs) from a VCD of
`ncinterp board-sim --vcd` (which dumps two time units per clock) and prints, per axis,
the shortest step high time, step low time, dir set-up before a rising step edge and dir
hold after it, in clocks and ns. docs/board.md quotes its output.
"""
import argparse
import re
import sys


def read_vcd(path, names):
    ids, changes, t = {}, {n: [] for n in names}, 0
    scope = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line.startswith("$scope"):
                scope.append(line.split()[2])
            elif line.startswith("$upscope"):
                scope.pop()
            elif line.startswith("$var"):
                parts = line.split()
                if scope and scope[-1] == "board_core" and parts[4] in names:
                    ids[parts[3]] = parts[4]
            elif line.startswith("#"):
                t = int(line[1:])
            elif line and line[0] in "01" and line[1:] in ids:
                changes[ids[line[1:]]].append((t, int(line[0])))
    return changes


def axis_timing(step, dir_):
    rises = [t for t, v in step if v == 1]
    falls = [t for t, v in step if v == 0 and t > 0]
    dir_changes = [t for t, _ in dir_[1:]]
    high = [f - r for r, f in zip(rises, [f for f in falls if f > rises[0]])] if rises else []
    low = [r2 - f for f, r2 in zip([f for f in falls if f > rises[0]], rises[1:])] if rises else []
    setup = [r - max([d for d in dir_changes if d <= r], default=-10**12) for r in rises]
    hold = [min([d for d in dir_changes if d > r], default=10**12) - r for r in rises]
    return {"pulses": len(rises), "high": min(high, default=None), "low": min(low, default=None),
            "setup": min([s for s in setup if s < 10**11], default=None),
            "hold": min([h for h in hold if h < 10**11], default=None)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("vcd")
    ap.add_argument("--clock-hz", type=float, default=12e6)
    a = ap.parse_args()
    names = ["step_x_o", "dir_x_o", "step_y_o", "dir_y_o"]
    ch = read_vcd(a.vcd, names)
    ns_per_clock = 1e9 / a.clock_hz
    print(f"{'axis':4} {'pulses':>6} {'measure':>8} {'clocks':>6} {'ns':>8}")
    for axis in "xy":
        t = axis_timing(ch[f"step_{axis}_o"], ch[f"dir_{axis}_o"])
        for key in ("high", "low", "setup", "hold"):
            v = t[key]
            clocks = None if v is None else v / 2  # two VCD time units per clock
            print(f"{axis:4} {t['pulses']:6} {key:>8} {'-' if clocks is None else f'{clocks:6.0f}':>6} "
                  f"{'-' if clocks is None else f'{clocks * ns_per_clock:8.0f}':>8}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
