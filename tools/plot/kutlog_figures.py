#!/usr/bin/python3
"""Draws kutlog's figures with matplotlib from the CSV the tools write.

    kutlog-curves --figure 2 --format csv >figure-2.csv
    kutlog_figures.py --figure 2 --data figure-2.csv --output figure-2.png

Figures and the tables they read:
  2, lobe  kutlog-curves --figure 2 (or lobe): F_kutlog, Blinn-Phong and Schlick against the angle
  3        kutlog-curves --figure 3: delta in the epicenter zone against n
  9        kutlog-curves --figure 9: energy error of the fitted and of the exact coef against n
  albedo   kutlog-curves --figure albedo: white furnace, directional albedo against incidence
  shape    kutlog-curves --figure shape: the largest |F_kutlog - t^n| against n, per k, a panel
           per Q
  ulp      kutlog-ulp --function F --profile: max ULP error per input bucket, per arch
  rmse     kutlog-pathtrace: RMSE against a high-spp reference against spp, lobe and uniform
           sampling

Needs only the standard library and matplotlib (Debian: python3-matplotlib, for /usr/bin/python3).
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display, no GUI toolkit
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
from matplotlib.ticker import LogLocator  # noqa: E402

# 1200 x 800 pixels, text sized for a README column.
FIGURE_INCHES = (12, 8)
DPI = 100
STYLE = {
    "font.size": 13,
    "axes.titlesize": 17,
    "axes.labelsize": 15,
    "legend.fontsize": 12,
    "lines.linewidth": 2,
    "axes.grid": True,
    "grid.color": "0.85",
    "axes.titlepad": 14,
    "axes.labelpad": 8,
    "figure.constrained_layout.h_pad": 0.15,  # inches around the axes
    "figure.constrained_layout.w_pad": 0.15,
    "savefig.facecolor": "white",
}
# The exact coef's energy error is rounding and often exactly 0; drawn at this floor on the log
# axis rather than left out.
EXACT_ZERO_FLOOR = 1e-17


def read_table(path):
    """The CSV's rows as dicts, numbers as float where a field parses as one."""
    with (sys.stdin if path == "-" else open(path, newline="")) as stream:
        rows = list(csv.DictReader(stream))
    if not rows:
        sys.exit(f"kutlog_figures: {path}: no data rows")

    def value(text):
        try:
            return float(text)
        except ValueError:
            return text

    return [{key: value(text) for key, text in row.items()} for row in rows]


def column(rows, name):
    try:
        return [row[name] for row in rows]
    except KeyError:
        sys.exit(f"kutlog_figures: the data has no column '{name}' (columns: {', '.join(rows[0])});"
                 " is it the table of this --figure?")


def parameters(rows, *names):
    """'n = 50, k = 5, Q = 0.5' from the parameter columns every row repeats."""
    return ", ".join(f"{name} = {rows[0][name]:g}" for name in names)


def new_axes():
    figure, axes = plt.subplots(figsize=FIGURE_INCHES, dpi=DPI, layout="constrained")
    return figure, axes


def log_grid(axes, axis):
    """Decades labelled, 2..9 as a faint minor grid."""
    target = axes.xaxis if axis == "x" else axes.yaxis
    target.set_minor_locator(LogLocator(subs=range(2, 10)))
    axes.grid(True, which="minor", axis=axis, color="0.93")


def n_axis(axes, n):
    """A logarithmic axis of n, labelled in plain numbers at 1, 2 and 5 times the decades."""
    axes.set_xscale("log")
    log_grid(axes, "x")
    ticks = [m * 10**e for e in range(6) for m in (1, 2, 5) if min(n) / 2 <= m * 10**e <= max(n)]
    axes.set_xticks(ticks, [f"{tick:g}" for tick in ticks])


def lobes(rows, title):
    figure, axes = new_axes()
    angle = column(rows, "angle")
    axes.plot(angle, column(rows, "kutlog"), label=r"$F_\mathrm{kutlog} = \cos^k(c\,x)$")
    axes.plot(angle, column(rows, "blinn_phong"), label=r"Blinn-Phong $\cos^n(x)$")
    axes.plot(angle, column(rows, "schlick"), label=r"Schlick $t\,/\,(n - n\,t + t)$")
    axes.axhline(rows[0]["Q"], color="C3", linestyle="--",
                 label=r"$Q$: $F_\mathrm{kutlog}$ = Blinn-Phong at the anchor")
    axes.set(title=f"{title} ({parameters(rows, 'n', 'k', 'Q')})",
             xlabel="angle $x$ (radians)", ylabel="$F(x)$", xlim=(0, max(angle)))
    axes.legend(loc="best")
    return figure


def epicenter_errors(rows):
    figure, axes = new_axes()
    n = column(rows, "n")
    axes.plot(n, column(rows, "kutlog_delta_percent"), label=r"$F_\mathrm{kutlog}$")
    axes.plot(n, column(rows, "schlick_delta_percent"), label="Schlick")
    n_axis(axes, n)
    axes.set(title="Figure 3: max relative error where $\\cos^n(x) \\geq 0.6$ "
                   f"({parameters(rows, 'k', 'Q')})",
             xlabel="$n$", ylabel=r"$\delta$ (%)", ylim=(0, None))
    axes.legend(loc="best")
    return figure


def energy_errors(rows):
    figure, axes = new_axes()
    n = column(rows, "n")
    exact = [max(error, EXACT_ZERO_FLOOR) for error in column(rows, "exact_coef_error")]
    axes.plot(n, column(rows, "fitted_coef_error"), label="the article's fitted coef")
    axes.plot(n, exact, linewidth=1,
              label=f"kutlog's exact coef (quadrature check; 0 drawn at {EXACT_ZERO_FLOOR:g})")
    n_axis(axes, n)
    axes.set_yscale("log")
    # Headroom above the fitted curve for the legend.
    axes.set(title=r"Figure 9: energy error $\Delta = |\mathrm{coef}\;2\pi \int - 1|$ "
                   f"({parameters(rows, 'k', 'Q')})",
             xlabel="$n$", ylabel=r"$\Delta$", ylim=(1e-18, 10))
    axes.yaxis.set_major_locator(LogLocator(numticks=11))  # every other decade
    axes.legend(loc="upper right")
    return figure


def albedo(rows):
    figure, axes = new_axes()
    degrees = column(rows, "incidence_degrees")
    axes.plot(degrees, column(rows, "blinn_exact_coef"), label="Blinn use, exact coef")
    axes.plot(degrees, column(rows, "blinn_fitted_coef"),
              label="Blinn use, the article's fitted coef")
    axes.plot(degrees, column(rows, "phong_exact_coef"), label="Phong use, exact coef")
    axes.plot(degrees, column(rows, "phong_fitted_coef"),
              label="Phong use, the article's fitted coef")
    axes.axhline(1, color="C4", linestyle="--", label="energy conservation: at most 1")
    # Zoomed on 1, where the fitted coef's excess shows; the Phong use, ~cos(theta_i), leaves
    # the frame below 0.9.
    axes.set(title=f"White furnace: directional albedo near 1 ({parameters(rows, 'n', 'k', 'Q')})",
             xlabel="incidence angle (degrees)", ylabel="albedo", xlim=(0, 90), ylim=(0.9, 1.02))
    axes.legend(loc="lower right")
    return figure


def shape_gaps(rows):
    """A panel per Q, a line per k: the largest gap to t^n against n, on shared axes."""
    anchors = list(dict.fromkeys(column(rows, "Q")))
    columns = 2 if len(anchors) > 1 else 1
    figure, panels = plt.subplots((len(anchors) + columns - 1) // columns, columns,
                                  figsize=FIGURE_INCHES, dpi=DPI, layout="constrained",
                                  sharex=True, sharey=True, squeeze=False)
    n = column(rows, "n")
    # Decades, and 3.2 times each between them (32 is one of the README table's n).
    ticks = [tick for tick in (10, 32, 100, 320, 1000, 3200, 10000) if min(n) <= tick <= max(n)]
    for axes, anchor in zip(panels.flat, anchors):
        for k in dict.fromkeys(column(rows, "k")):
            mine = [row for row in rows if row["Q"] == anchor and row["k"] == k]
            axes.plot(column(mine, "n"), column(mine, "max_gap"), label=f"k = {k:g}")
        axes.set_xscale("log")
        log_grid(axes, "x")
        axes.set_title(f"Q = {anchor:g}")
    for axes in panels[-1]:
        axes.set_xlabel("$n$")
    for axes in panels[:, 0]:
        axes.set_ylabel(r"max $|F_\mathrm{kutlog} - t^n|$")
    # Shared axes: set once, after every line is drawn.
    panels[0, 0].set_xticks(ticks, [f"{tick:g}" for tick in ticks])
    panels[0, 0].set(xlim=(min(n), max(n)), ylim=(0, 1.05 * max(column(rows, "max_gap"))))
    # Above Q = 0.25's lines (or the only panel's), where the panel is empty.
    panels.flat[min(1, len(anchors) - 1)].legend(loc="upper right", ncols=3)
    figure.suptitle(r"Largest gap between $F_\mathrm{kutlog}$ and Blinn-Phong $t^n$ over the "
                    "angle (the peak is 1)", fontsize=STYLE["axes.titlesize"])
    return figure


def ulp_errors(rows):
    figure, axes = new_axes()
    functions = list(dict.fromkeys(column(rows, "function")))
    series = {}
    for row in rows:
        name = f"{row['function']} {row['arch']}" if len(functions) > 1 else row["arch"]
        xs, ys = series.setdefault(name, ([], []))
        xs.append(row["input"])
        ys.append(row["max_ulp"])
    inputs = column(rows, "input")
    positive = [x for x in inputs if x > 0]
    # A domain spanning decades (log, pow's x) reads on a logarithmic axis (where a 0 is not
    # drawn).
    log_x = min(inputs) >= 0 and bool(positive) and max(positive) / min(positive) > 1e3
    for name, (xs, ys) in series.items():
        axes.scatter(xs, ys, s=6, marker="s", linewidths=0, label=name)
    bound, promise = rows[0]["bound_ulp"], rows[0]["promised_ulp"]
    # In black, whatever the number of series: the palette's colors are theirs.
    axes.axhline(bound, color="black", linestyle="--", label=f"bound {bound:.2f} ULP")
    axes.axhline(promise, color="black", linestyle=":", label=f"promise {promise:.1f} ULP")
    count = len(series)
    if log_x:
        axes.set_xscale("log")
        log_grid(axes, "x")
    domain = str(rows[0]["domain"]).split(";")[0]
    axes.set(title=f"{rows[0]['kernel']}: ULP error against the input, every float of {domain}",
             xlabel="x" if functions[0].startswith("pow") else "input",
             ylabel="max ULP error per bucket")
    # Beside the axes: the points fill the plot, and pow has a series per exponent and arch.
    axes.legend(loc="upper left", bbox_to_anchor=(1.01, 1), markerscale=2,
                ncols=1 if count <= 14 else 2)
    return figure


def sampling_errors(rows):
    figure, axes = new_axes()
    spp = column(rows, "spp")
    lobe = column(rows, "rmse_lobe")
    axes.plot(spp, lobe, marker="o", label=r"importance sampling the $F_\mathrm{kutlog}$ lobe")
    axes.plot(spp, column(rows, "rmse_uniform"), marker="s",
              label=r"uniform hemisphere sampling (pdf $1/2\pi$)")
    # Monte Carlo's rate, through the lobe's first point: an unbiased estimate of finite
    # variance follows it.
    axes.plot(spp, [lobe[0] * (spp[0] / s) ** 0.5 for s in spp], color="0.5", linestyle="--",
              linewidth=1, label=r"$\propto 1/\sqrt{\mathrm{spp}}$")
    axes.set_xscale("log", base=2)
    axes.set_yscale("log")
    log_grid(axes, "y")
    axes.set_xticks(spp, [f"{s:g}" for s in spp])
    axes.set(title=f"Glossy sphere under a sky: RMSE against a {rows[0]['reference_spp']:g}-spp "
                   f"reference ({parameters(rows, 'n', 'k', 'Q')})",
             xlabel="samples per pixel", ylabel="RMSE (radiance)")
    axes.legend(loc="best")
    return figure


FIGURES = {
    "2": lambda rows: lobes(rows, "Figure 2: the lobes"),
    "lobe": lambda rows: lobes(rows, "The lobes"),
    "3": epicenter_errors,
    "9": energy_errors,
    "albedo": albedo,
    "shape": shape_gaps,
    "ulp": ulp_errors,
    "rmse": sampling_errors,
}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--figure", required=True, choices=FIGURES)
    parser.add_argument("--data", required=True, help="the tool's CSV, or - for standard input")
    parser.add_argument("--output", "-o", required=True, help="the PNG to write")
    arguments = parser.parse_args()
    with plt.rc_context(STYLE):
        figure = FIGURES[arguments.figure](read_table(arguments.data))
        figure.savefig(arguments.output, format="png")
    print(f"kutlog_figures: wrote {arguments.output}", file=sys.stderr)


if __name__ == "__main__":
    main()
