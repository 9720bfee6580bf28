#!/usr/bin/env python3
"""Plots a shot's cost from speed_bench's JSON output (--benchmark_out).

    scripts/plot_speed.py SPEED.json OUT.png

Left: milliseconds per shot against the element count (hemicube 300^2,
automatic regions, every core). Right: against the hemicube resolution
(about 90 000 elements). Medians of the repetitions; drawn by gnuplot.
"""
import json
import statistics
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path


def medians(path):
    """{(kelements, hemicube, threads, regions): (elements, ms per shot)}"""
    runs = defaultdict(list)
    for b in json.loads(Path(path).read_text())["benchmarks"]:
        if b.get("run_type") != "iteration" or not b["name"].startswith("scale/"):
            continue
        fields = dict(part.split(":") for part in b["name"].split("/")[1:] if ":" in part)
        key = tuple(int(fields[k]) for k in ("kelements", "hemicube", "threads", "regions"))
        runs[key].append((b["elements"], b["ms_per_shot"]))
    return {k: (v[0][0], statistics.median(ms for _, ms in v)) for k, v in runs.items()}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    figures = medians(sys.argv[1])
    by_elements = sorted((e, ms) for (k, n, t, r), (e, ms) in figures.items() if n == 300 and t == 0 and r == 1)
    by_resolution = sorted((n, ms) for (k, n, t, r), (e, ms) in figures.items() if k == 100 and t == 0 and r == 1)
    if not by_elements or not by_resolution:
        sys.exit("plot_speed: no scale figures in " + sys.argv[1])
    with tempfile.TemporaryDirectory() as tmp:
        a, b = Path(tmp, "elements.dat"), Path(tmp, "resolution.dat")
        a.write_text("".join(f"{e} {ms}\n" for e, ms in by_elements))
        b.write_text("".join(f"{n} {ms}\n" for n, ms in by_resolution))
        script = f"""
set terminal pngcairo size 1100,450 font ",10" noenhanced
set output "{sys.argv[2]}"
set multiplot layout 1,2 title "Regio: milliseconds per hemicube shot (medians, speed_bench)"
set grid
set logscale xy
set xlabel "elements (hemicube 300 x 300)"
set ylabel "ms per shot"
plot "{a}" using 1:2 with linespoints pointtype 7 title "automatic regions"
unset logscale
set logscale y
set xlabel "hemicube resolution N (about 90 000 elements)"
set xtics (150, 300, 600)
plot "{b}" using 1:2 with linespoints pointtype 7 title "automatic regions"
unset multiplot
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)


if __name__ == "__main__":
    main()
