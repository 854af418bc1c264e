"""The per-ray cost table from docs/cost/per_ray.sh's CSV: penumbra's render time over
POV-Ray's trace time, one ray per pixel each, slowest first, and the geometric mean."""
import csv
import math
import sys


def main(path):
    rows = list(csv.DictReader(open(path)))
    before = any(r.get("base_render_s") for r in rows)
    table = []
    for r in rows:
        pov, pen = float(r["povray_trace_s"]), float(r["penumbra_render_s"])
        if pov <= 0 or pen <= 0:
            continue
        prev = float(r["base_render_s"]) / pov if r.get("base_render_s") else None
        table.append((pen / pov, r["scene"], pov, pen, prev))
    table.sort(reverse=True)
    print("| scene | POV-Ray trace s | penumbra render s | penumbra / POV-Ray |"
          + (" before (BASE) |" if before else ""))
    print("| --- | ---: | ---: | ---: |" + (" ---: |" if before else ""))
    for ratio, scene, pov, pen, prev in table:
        extra = f" {prev:.2f}x |" if before and prev else (" |" if before else "")
        print(f"| {scene} | {pov:.3f} | {pen:.2f} | {ratio:.2f}x |{extra}")
    logs = [math.log(t[0]) for t in table]
    mean = math.exp(sum(logs) / len(logs))
    print()
    print(f"- {len(table)} scenes; geometric mean of penumbra / POV-Ray {mean:.2f}x; "
          f"penumbra slower at {sum(t[0] > 1 for t in table)}, more than 1.5x slower at "
          f"{sum(t[0] > 1.5 for t in table)}.")
    old = [t for t in table if t[4]]
    if old:
        was = math.exp(sum(math.log(t[4]) for t in old) / len(old))
        print(f"- BASE over the same {len(old)} scenes: geometric mean {was:.2f}x; slower at "
              f"{sum(t[4] > 1 for t in old)}, more than 1.5x slower at "
              f"{sum(t[4] > 1.5 for t in old)}.")


if __name__ == "__main__":
    main(*sys.argv[1:])
