#!/usr/bin/python3
"""Plots the accuracy lab's CSV (bench/accuracy_lab.cpp) like the paper's Fig. 8
(Rusinkiewicz 2004): relative error against noise, one panel per surface, curvature
on the top row and C on the bottom, log scale; and writes a Markdown table of the
clean, 2%- and 5%-noise errors.

    scripts/plot_accuracy.py accuracy.csv OUT_DIR

writes OUT_DIR/fig8.png, OUT_DIR/fig8.svg and OUT_DIR/table.md. Needs Debian's
python3-matplotlib.
"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    rows = defaultdict(dict)  # (surface, method) -> noise -> (curvature, dcurv)
    surfaces, methods = [], []
    with open(path) as f:
        for r in csv.DictReader(f):
            s, m = r["surface"], r["method"]
            if s not in surfaces:
                surfaces.append(s)
            if m not in methods:
                methods.append(m)
            rows[(s, m)][float(r["noise"])] = (float(r["curvature_error"]), float(r["dcurv_error"]))
    return surfaces, methods, rows


def plot(surfaces, methods, rows, out_dir):
    fig, axes = plt.subplots(2, len(surfaces), figsize=(4.2 * len(surfaces), 7.5), squeeze=False)
    styles = ["-o", "-s", "-^", "-v", "-D", "--x", "--+", ":.", ":1", "-.*", "-.p"]
    for col, s in enumerate(surfaces):
        for row, (label, k) in enumerate((("curvature error", 0), ("C error", 1))):
            ax = axes[row][col]
            for i, m in enumerate(methods):
                pts = sorted(rows[(s, m)].items())
                ax.plot([100 * n for n, _ in pts], [max(v[k], 1e-7) for _, v in pts], styles[i % len(styles)],
                        label=m, markersize=4, linewidth=1.2)
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
            ax.set_xlabel("noise (% of median edge)")
            if col == 0:
                ax.set_ylabel(label + " (relative RMS)")
            ax.set_title(f"{s}: {label}", fontsize=10)
    axes[0][0].legend(fontsize=8, loc="lower right")
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out_dir, "fig8." + ext), dpi=90)


def pct(x):
    return "-" if x != x else f"{100 * x:.3g}%"  # NaN: the method gives no C


NOISES = (0.0, 0.02, 0.05)


def table(surfaces, methods, rows, out_dir):
    lines = ["| surface | method | curvature, clean | C, clean | curvature, 2% noise | C, 2% noise "
             "| curvature, 5% noise | C, 5% noise |",
             "|---|---|---|---|---|---|---|---|"]
    for s in surfaces:
        for m in methods:
            r = rows[(s, m)]
            if any(n not in r for n in NOISES):
                continue
            cells = " | ".join(f"{pct(r[n][0])} | {pct(r[n][1])}" for n in NOISES)
            lines.append(f"| {s} | {m} | {cells} |")
    with open(os.path.join(out_dir, "table.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_accuracy.py accuracy.csv OUT_DIR")
    surfaces, methods, rows = read(sys.argv[1])
    os.makedirs(sys.argv[2], exist_ok=True)
    plot(surfaces, methods, rows, sys.argv[2])
    table(surfaces, methods, rows, sys.argv[2])


if __name__ == "__main__":
    main()
