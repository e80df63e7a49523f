"""Tables (CSV, Markdown) and plots (PNG) of the study records."""
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def write_csv(path, records, columns):
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        for r in records:
            w.writerow([_csv_value(r.get(c, "")) for c in columns])
    os.replace(tmp, path)


def _csv_value(v):
    if isinstance(v, float):
        return repr(v)
    return v


def fmt(v, kind=None):
    if v is None or v == "":
        return ""
    if isinstance(v, str):
        return v
    if isinstance(v, int) and kind is None:
        return f"{v:,}".replace(",", " ")
    if isinstance(v, float) and (math.isnan(v) or math.isinf(v)):
        return str(v)
    if kind == "t":
        return f"{v:.3f}" if v < 10 else f"{v:.1f}"
    if kind == "e":
        return f"{v:.2e}"
    if kind == "f":
        return f"{v:.2f}"
    if kind == "f3":  # ratios close to 1
        return f"{v:.4f}"
    if isinstance(v, float):
        return f"{v:.3g}"
    return str(v)


def markdown_table(records, columns):
    """columns: list of (key, header, kind)."""
    out = ["| " + " | ".join(h for _, h, _ in columns) + " |", "|" + "---|" * len(columns)]
    for r in records:
        out.append("| " + " | ".join(fmt(r.get(k, ""), kind) for k, _, kind in columns) + " |")
    return "\n".join(out) + "\n"


def fit_rate(x, y):
    """Least-squares slope of log y against log x (None with fewer than 2 usable points)."""
    pts = [(math.log(a), math.log(b)) for a, b in zip(x, y) if a and b and a > 0 and b > 0]
    if len(pts) < 2:
        return None
    X = np.array([p[0] for p in pts])
    Y = np.array([p[1] for p in pts])
    return float(np.polyfit(X, Y, 1)[0])


COLORS = {"quad4": "tab:blue", "tria3": "tab:orange", "hexa8": "tab:green", "tetra4": "tab:red"}


def style(label):
    """Line style of a series labelled '<element> [<variant> ...]': colour by element, line by variant
    (open / no variant: solid, STANDARD: dashed, PENALISATION: dotted, one marker per coefficient)."""
    words = label.split()
    kw = {"color": COLORS.get(words[0]) if words else None, "linestyle": "-", "marker": "o"}
    rest = " ".join(words[1:])
    if "STANDARD" in rest:
        kw.update(linestyle="--", marker="s", markerfacecolor="none")
    elif "PENALISATION" in rest:
        kw.update(linestyle=":", marker="^" if "e+10" in rest else "v")
    return kw


def _save(fig, path):
    fig.tight_layout()
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    plt.close(fig)
    os.replace(tmp, path)


def plot_error_vs_dofs(path, series, fit_last=4):
    """series: {element: [(dofs, h, l2, energy), ...]} -> two panels, fitted rates in h in the legend."""
    fig, axes = plt.subplots(1, 2, figsize=(12, 5.5))
    for ax, idx, name, theory in ((axes[0], 3, "energy norm", 1), (axes[1], 2, "L2 norm", 2)):
        for el, pts in series.items():
            pts = sorted(p for p in pts if p[idx])
            if not pts:
                continue
            d = [p[0] for p in pts]
            e = [p[idx] for p in pts]
            rate = fit_rate([p[1] for p in pts[-fit_last:]], e[-fit_last:])
            label = f"{el}: rate in h {rate:.2f}" if rate is not None else el
            ax.loglog(d, e, label=label, **style(el))
        ax.set_xlabel("DOFs")
        ax.set_ylabel(f"relative error, {name}")
        ax.set_title(f"{name} (theory: h^{theory})")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    _save(fig, path)


def plot_trade(path, series):
    """series: {label: [(wall, l2, energy), ...]}: error against wall time."""
    fig, axes = plt.subplots(1, 2, figsize=(12, 5.5))
    for ax, idx, name in ((axes[0], 2, "energy norm"), (axes[1], 1, "L2 norm")):
        for label, pts in series.items():
            pts = sorted(p for p in pts if p[idx] and p[0])
            if pts:
                ax.loglog([p[0] for p in pts], [p[idx] for p in pts], label=label, **style(label))
        ax.set_xlabel("wall time of the run (s)")
        ax.set_ylabel(f"relative error, {name}")
        ax.set_title(f"speed vs accuracy ({name})")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    _save(fig, path)


def plot_time_vs_dofs(path, series, fit_min_dofs=2e4):
    """series: {label: [(dofs, seconds), ...]}: log-log, fitted exponent over dofs >= fit_min_dofs."""
    fig, ax = plt.subplots(figsize=(7, 5))
    for label, pts in series.items():
        pts = sorted(p for p in pts if p[1] and p[1] > 0)
        if not pts:
            continue
        big = [p for p in pts if p[0] >= fit_min_dofs]
        rate = fit_rate([p[0] for p in big], [p[1] for p in big])
        kw = style(label) if "factorisation" not in label else {"marker": "x", "color": "k"}
        ax.loglog([p[0] for p in pts], [p[1] for p in pts],
                  label=f"{label}: exponent {rate:.2f}" if rate is not None else label, **kw)
    ax.set_xlabel("DOFs")
    ax.set_ylabel("wall time (s)")
    ax.set_title(f"time vs DOFs (exponent fitted on DOFs >= {fit_min_dofs:.0e})")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    _save(fig, path)


def plot_sweep(path, title, xlabel, series, threshold=1e-9, logx=True,
               ylabel="error (max of L2 rel., strain rel.)"):
    """series: {label: [(x, error, alarmed), ...]}: error vs parameter, filled markers = alarm."""
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, pts in series.items():
        pts = sorted(pts)
        xs = [p[0] for p in pts]
        ys = [max(p[1], 1e-18) if p[1] is not None else float("nan") for p in pts]
        line, = ax.plot(xs, ys, "-", label=label)
        for x, y, alarmed in zip(xs, ys, [p[2] for p in pts]):
            ax.plot([x], [y], "o" if alarmed else "x", color=line.get_color(), markersize=7 if alarmed else 6,
                    markerfacecolor="none" if alarmed else None)
    ax.axhline(threshold, color="k", linestyle="--", linewidth=0.8)
    ax.set_yscale("log")
    if logx:
        ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title + "\n(o = alarm in the .mess, x = none; dashed line: 1e-9)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    _save(fig, path)


def plot_penalty(path, records):
    """Penalty sweep: L2 (left) and energy (right) relative errors against COEF_PENA_CONT, one line per
    element and N, the analytic L2 error p/k dashed; a run that stopped with an error (a singular
    system or a Newton failure, its cause named in the .mess) is a red triangle on the top edge."""
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    keys = sorted({(r["element"], r["N"]) for r in records if r.get("algo") == "PENALISATION"},
                  key=lambda k: (list(COLORS).index(k[0]) if k[0] in COLORS else 9, k[1]))
    styles = ["-", "--", ":", "-."]
    for ax, column, name in ((axes[0], "l2_rel", "L2 norm"), (axes[1], "energy_rel", "energy norm")):
        top, labelled = 3e1, False
        for element, n in keys:
            rows = sorted((r for r in records if r.get("algo") == "PENALISATION" and r["element"] == element
                           and r["N"] == n), key=lambda r: r["coef"])
            ok = [(r["coef"], max(r[column], 1e-18)) for r in rows if r.get(column) is not None]
            style = styles[[m for e, m in keys if e == element].index(n) % len(styles)]
            if ok:
                ax.plot([x for x, _ in ok], [y for _, y in ok], style, marker="o", markersize=4,
                        color=COLORS.get(element), label=f"{element} N={n}")
            stopped = [r["coef"] for r in rows if r.get(column) is None]
            if stopped:
                ax.plot(stopped, [top] * len(stopped), "^", color="red", markersize=8,
                        label=None if labelled else "run stopped with an error naming its cause")
                labelled = True
        if column == "l2_rel" and keys:
            # p/k of the first element (the analytic error is proportional to 1/k): over every coefficient
            first = [r for r in records if r.get("expected_l2") and (r["element"], r["N"]) == keys[0]]
            if first:
                c = first[0]["expected_l2"] * first[0]["coef"]
                coefs = sorted({r["coef"] for r in records if r.get("algo") == "PENALISATION"})
                ax.plot(coefs, [c / x for x in coefs], "k--", linewidth=1,
                        label=f"analytic p/k ({keys[0][0]} N={keys[0][1]})")
        ax.axhline(1e-9, color="grey", linestyle=":", linewidth=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(1e-16, 1e2)
        ax.set_xlabel("COEF_PENA_CONT")
        ax.set_ylabel(f"relative error, {name}")
        ax.set_title(f"PENALISATION: {name}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    _save(fig, path)


QUADRATURE_MARKERS = {"degree 1": "v", "degree 2": "^", "degree 3": "s", "degree 4": "D", "degree 5": "P",
                      "degree 6": "*", "catalogue": "o"}


def _quadrature_style(element, rule):
    return {"color": COLORS.get(element), "marker": QUADRATURE_MARKERS.get(rule, "x"),
            "linestyle": {"degree 1": ":", "degree 2": "-.", "catalogue": "-"}.get(rule, "--"),
            "markerfacecolor": "none" if rule == "catalogue" else None}


def plot_quadrature_ratio(path, series):
    """series: {(element, contact, rule): [(dofs, l2_ratio, energy_ratio), ...]}: error of each rule divided
    by the catalogue rule's on the same mesh; columns open / contact, rows energy / L2."""
    contacts = sorted({k[1] for k in series}, key=lambda c: (c != "open", c))
    fig, axes = plt.subplots(2, max(1, len(contacts)), figsize=(6.5 * max(1, len(contacts)), 9), squeeze=False)
    for col, contact in enumerate(contacts):
        for row, idx, name in ((0, 2, "energy norm"), (1, 1, "L2 norm")):
            ax = axes[row][col]
            for (element, c, rule), pts in series.items():
                pts = sorted(p for p in pts if c == contact and p[idx])
                if pts:
                    ax.semilogx([p[0] for p in pts], [p[idx] for p in pts], label=f"{element} {rule}",
                                **_quadrature_style(element, rule))
            ax.axhline(1.0, color="k", linewidth=0.8)
            ax.set_xlabel("DOFs")
            ax.set_ylabel(f"error / error with the catalogue rule ({name})")
            ax.set_title(f"{contact}: {name}")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7, ncol=2)
    _save(fig, path)


def plot_quadrature_error(path, series):
    """series: {(element, contact, rule): [(dofs, l2, energy), ...]}: error vs DOFs per rule."""
    fig, axes = plt.subplots(1, 2, figsize=(12, 5.5))
    for ax, idx, name in ((axes[0], 2, "energy norm"), (axes[1], 1, "L2 norm")):
        for (element, contact, rule), pts in series.items():
            pts = sorted(p for p in pts if p[idx])
            if pts:
                kw = _quadrature_style(element, rule)
                if contact != "open":
                    kw["alpha"] = 0.55
                ax.loglog([p[0] for p in pts], [p[idx] for p in pts], label=f"{element} {contact} {rule}", **kw)
        ax.set_xlabel("DOFs")
        ax.set_ylabel(f"relative error, {name}")
        ax.set_title(f"{name} per sub-cell rule")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
    _save(fig, path)
