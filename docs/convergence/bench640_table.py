#!/usr/bin/env python3
"""The equal-error table of the 640x480 benchmark: for each scene and each of POV-Ray's
quality settings, the time penumbra takes to reach POV-Ray's RMSE there, from the CSVs that
docs/convergence/bench640.sh writes (one folder of scenes per penumbra configuration).

Usage: bench640_table.py NAME=DIR [NAME=DIR...] > table.md

penumbra's time to an error interpolates log(seconds) linearly in log(RMSE) between the
sample counts that bracket it. Below its smallest sample count's error the time is that
count's ("<=", so the speed-up is a lower bound, ">="); past its largest, the target is not
reached and the speed-up is an upper bound ("<"). POV-Ray's time is its own parse + render
time (start-up apart, as the CSV's process_seconds shows); both ran one thread, side by side
in one run.

Every time is the fastest of the runs measured, for both renderers alike: penumbra's seeds
(two renders of the same sample count, seconds_low) and POV-Ray's runs of a setting (once in
each configuration's benchmark, so twice when both are given). On this shared machine a
render's time moves by up to half from one run to the next, upwards only: the fastest run
is the one least disturbed, and a ratio of single runs flipped from 0.74x to 1.33x between
two runs of the same binaries.
"""
import csv
import math
import os
import sys


def read(path):
    pen, pov = [], []
    with open(path) as f:
        for row in csv.DictReader(f):
            point = (float(row["seconds_low"]), float(row["rmse"]))
            if row["method"] == "penumbra":
                pen.append((float(row["spp"]), point))
            else:
                pov.append((row["setting"], point))
    pen.sort()
    return [p for _, p in pen], pov


def time_to(curve, target):
    """(seconds, bound): bound is '<=' below the first point, '>' past the last, '' else."""
    if target >= curve[0][1]:
        return curve[0][0], "<="
    for (t0, e0), (t1, e1) in zip(curve, curve[1:]):
        if e0 >= target >= e1 and e0 > e1:
            f = (math.log(e0) - math.log(target)) / (math.log(e0) - math.log(e1))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0))), ""
    return curve[-1][0], ">"


def main():
    configs = [a.split("=", 1) for a in sys.argv[1:]]
    scenes = sorted({s for _, d in configs for s in os.listdir(d)
                     if os.path.exists(os.path.join(d, s, "converge.csv"))})
    settings = ["-A", "+A0.3", "+AM2 +R3", "+AM2 +R4"]
    head = "| scene | POV-Ray | POV-Ray s | RMSE |"
    rule = "| --- | --- | ---: | ---: |"
    for name, _ in configs:
        head += f" {name} s | speed-up |"
        rule += " ---: | ---: |"
    print(head)
    print(rule)
    logs = {name: [] for name, _ in configs}
    wins = {name: 0 for name, _ in configs}
    total = 0
    for scene in scenes:
        curves = {}
        pov = {}
        for name, d in configs:
            path = os.path.join(d, scene, "converge.csv")
            if os.path.exists(path):
                curves[name], pov_rows = read(path)
                for setting, (seconds, rmse) in pov_rows:
                    fastest = min(seconds, pov.get(setting, (seconds, rmse))[0])
                    pov[setting] = (fastest, rmse)
        for setting, (pov_s, pov_e) in [r for r in pov.items() if r[0] in settings]:
            line = f"| {scene} | `{setting}` | {pov_s:.2f} | {pov_e:.5f} |"
            total += 1
            for name, _ in configs:
                if name not in curves:
                    line += " - | - |"
                    continue
                t, bound = time_to(curves[name], pov_e)
                ratio = pov_s / t
                mark = {"<=": ">= ", ">": "< ", "": ""}[bound]
                shown = {"<=": "<= ", ">": "> ", "": ""}[bound]
                line += f" {shown}{t:.2f} | {mark}{ratio:.2f}x |"
                logs[name].append(math.log(ratio))
                wins[name] += ratio > 1.0 and bound != ">"
            print(line)
    print()
    for name, _ in configs:
        if logs[name]:
            g = math.exp(sum(logs[name]) / len(logs[name]))
            print(f"- {name}: faster than POV-Ray at {wins[name]} of {total} scene settings; "
                  f"geometric mean of the speed-ups {g:.2f}x (bounds taken as values).")


if __name__ == "__main__":
    main()
