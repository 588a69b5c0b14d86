#!/usr/bin/env python3
"""NACA 4-digit airfoil coordinates (Abbott & von Doenhoff formula) in the UIUC formats.

Usage: naca4.py 2412 [--points 81] [--lednicer] > naca2412.dat
Cosine spacing in x; thickness with the standard open trailing edge (-0.1015 x^4);
the surface points are offset normal to the camber line. Coordinates in chord lengths.
"""
import argparse
import math


def naca4(code, n):
    m, p, t = int(code[0]) / 100.0, int(code[1]) / 10.0, int(code[2:]) / 100.0
    upper, lower = [], []
    for i in range(n):
        x = 0.5 * (1.0 - math.cos(math.pi * i / (n - 1)))
        yt = 5 * t * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x**2
                      + 0.2843 * x**3 - 0.1015 * x**4)
        if m == 0 or p == 0:
            yc, dyc = 0.0, 0.0
        elif x < p:
            yc, dyc = m / p**2 * (2 * p * x - x * x), 2 * m / p**2 * (p - x)
        else:
            yc = m / (1 - p)**2 * ((1 - 2 * p) + 2 * p * x - x * x)
            dyc = 2 * m / (1 - p)**2 * (p - x)
        th = math.atan(dyc)
        upper.append((x - yt * math.sin(th), yc + yt * math.cos(th)))
        lower.append((x + yt * math.sin(th), yc - yt * math.cos(th)))
    return upper, lower  # both from the leading edge to the trailing edge


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("code")
    ap.add_argument("--points", type=int, default=81)
    ap.add_argument("--lednicer", action="store_true")
    a = ap.parse_args()
    upper, lower = naca4(a.code, a.points)
    print(f"NACA {a.code}")
    if a.lednicer:
        print(f"{len(upper)}.  {len(lower)}.")
        print()
        for x, y in upper:
            print(f" {x:.7f}  {y:.7f}")
        print()
        for x, y in lower:
            print(f" {x:.7f}  {y:.7f}")
    else:
        for x, y in reversed(upper):
            print(f" {x:.7f}  {y:.7f}")
        for x, y in lower[1:]:
            print(f" {x:.7f}  {y:.7f}")


if __name__ == "__main__":
    main()
