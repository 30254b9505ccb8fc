#!/usr/bin/env python3
"""Draws the report of `modeflow validate` (tools/validate/README.md).

    python3 report.py DIR       reads DIR/results.json, writes DIR/figures/*.png and
                                DIR/report.html (self-contained: the figures inline as base64)
    python3 report.py --check   exits 3 when matplotlib cannot be imported

`modeflow validate` runs this script (embedded in the binary) with Debian's python3 and
python3-matplotlib. Every figure is drawn from results.json alone.
"""
import base64
import html
import json
import math
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from PIL import Image
except ImportError as e:
    print(f"report.py: matplotlib is missing ({e}); install python3-matplotlib", file=sys.stderr)
    sys.exit(3)

FIGURE_DPI = 90


class WriteFailed(Exception):
    """A file of the report could not be written (a full disk, a quota): one line says which."""


def write_atomically(path, write):
    """Calls write(partial) on a file beside `path`, then renames it over `path`: a failed write
    leaves no file under the final name, and removes its partial one."""
    partial = path + ".tmp"
    try:
        write(partial)
        os.replace(partial, path)
    except OSError as e:
        try:
            os.remove(partial)
        except OSError:
            pass
        raise WriteFailed(f"cannot write {path}: {e.strerror or e}") from e


def save(fig, folder, name):
    path = os.path.join(folder, name + ".png")
    fig.tight_layout()

    def write(partial):
        try:
            fig.savefig(partial, dpi=FIGURE_DPI, format="png")
        finally:
            plt.close(fig)
        # 256 colours (Pillow comes with matplotlib): a third of the size, so the committed
        # figures stay small.
        Image.open(partial).convert("RGB").quantize(colors=256).save(partial, format="PNG",
                                                                     optimize=True)

    write_atomically(path, write)
    return path


# One function per study: (its results, the figures folder) -> [(png path, caption)].


def draw_convergence(data, folder):
    colours = {"velocity": "tab:blue", "neumann": "tab:green", "dirichlet": "tab:red"}
    styles = {"cut-cell": "-", "staircase": "--"}
    domains = sorted({s["domain"] for s in data["series"]}, key=lambda d: d != "disk")
    fig, axes = plt.subplots(1, len(domains), figsize=(5.2 * len(domains), 4.2), squeeze=False)
    for ax, domain in zip(axes[0], domains):
        series = [s for s in data["series"] if s["domain"] == domain]
        for s in series:
            ax.loglog(s["h"], s["max_relative_error"], styles[s["boundary"]], marker="o", ms=4,
                      color=colours[s["field"]],
                      label=f'{s["field"]}, {s["boundary"]}: order {s["order"]:.2f}')
        h = [min(x for s in series for x in s["h"]), max(x for s in series for x in s["h"])]
        top = max(e for s in series for e in s["max_relative_error"])
        for p, ls in ((1, ":"), (2, "-.")):
            ax.loglog(h, [top * (x / h[1]) ** p for x in h], ls, color="grey", lw=1, label=f"h^{p}")
        ax.set_xlabel("cell size h")
        ax.set_ylabel(f'max relative error, first {data["eigenvalues_compared"]} eigenvalues')
        ax.set_title(f"unit {domain}")
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    return [(save(fig, folder, "convergence"),
             "Eigenvalue error against the closed forms (Bessel roots) as the grid is refined: cut cells "
             "converge at second order, the staircase at first (seed Fig. 6.13).")]


def draw_integrators(data, folder):
    schemes = ["explicit", "rk4", "midpoint", "trapezoidal", "linearized"]
    fig, axes = plt.subplots(1, len(schemes), figsize=(20, 3.8))
    for ax, scheme in zip(axes, schemes):
        for s in (s for s in data["series"] if s["integrator"] == scheme):
            e0 = s["energy"][0]
            label = f'dt = {s["dt"]:g} (h|R|/|v| = {s["step_rate"]:.2f})'
            if "diverged_at" in s:
                label += f', diverged at t = {s["diverged_at"]:.2f}'
            ax.plot(s["time"], [e / e0 - 1.0 for e in s["energy"]], label=label)
        ax.set_title(scheme)
        ax.set_xlabel("time")
        ax.set_ylabel("E(t) / E(0) − 1")
        ax.legend(fontsize=7)
        ax.grid(True, alpha=0.3)
        if scheme == "explicit":
            ax.set_yscale("symlog", linthresh=1e-3)
    system = data["system"]
    rows = ", ".join(f'{r["integrator"]} ' + ("diverged" if r.get("diverged") or r.get("return_error") is None
                                                   else f'{r["return_error"]:.1e}')
                     for r in data["reversibility"])
    return [(save(fig, folder, "integrators"),
             f'Energy of an unforced inviscid flow in the unit disk ({system["modes"]} modes, '
             f'{system["resolution"]}², random initial state) over time: explicit Euler gains energy every step, '
             f'RK4 loses it slowly, the midpoint rule keeps it to round-off, the trapezoidal rule keeps it bounded, '
             f'the linearized rule (the midpoint rule frozen at an explicit predictor) keeps it to round-off too. '
             f'Forward {data["reversibility"][0]["steps"]} steps and back, relative distance from the start: {rows}.')]


def draw_mhd(data, folder):
    field, plain = data["runs"]
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 3.8))
    for run, style in ((field, "-"), (plain, ":")):
        tag = f'B0 = {run["magnetic_strength"]:g}'
        total = [k + m for k, m in zip(run["kinetic_energy"], run["magnetic_energy"])]
        left.plot(run["time"], run["kinetic_energy"], style, color="tab:blue", label=f"kinetic, {tag}")
        if run["magnetic_strength"] > 0:
            left.plot(run["time"], run["magnetic_energy"], style, color="tab:red", label=f"magnetic, {tag}")
            left.plot(run["time"], total, style, color="black", label=f"total, {tag}")
    left.set_xlabel("time")
    left.set_ylabel("energy")
    left.legend(fontsize=7)
    left.grid(True, alpha=0.3)
    random = data["random"]
    e0 = random["kinetic_energy"][0] + random["magnetic_energy"][0]
    total = [k + m for k, m in zip(random["kinetic_energy"], random["magnetic_energy"])]
    h0 = random["cross_helicity"][0]
    right.plot(random["time"], [(t - e0) / e0 for t in total], label="(E − E(0)) / E(0)")
    right.plot(random["time"], [(h - h0) / abs(h0) for h in random["cross_helicity"]],
               label="(H − H(0)) / |H(0)|, H = Σ v_i F_i")
    right.set_xlabel("time")
    right.set_title("invariants of a random flow in a random field (midpoint rule)", fontsize=9)
    right.legend(fontsize=7)
    right.grid(True, alpha=0.3)
    figures = [(save(fig, folder, "mhd_invariants"),
                f'The MHD rotor ({data["scene"]["modes"]} modes, {data["scene"]["resolution"][0]}², dt = '
                f'{data["scene"]["dt"]}): the field takes the rotor’s energy and gives it back, the total stays '
                f'constant (largest drift {field["max_relative_energy_drift"]:.1e}). Right: a random flow in a random '
                f'field in the unit disk (scenes/mhd_disk_2d.toml), where the cross helicity is not 0 by symmetry '
                f'as the rotor’s is: energy and cross helicity drift by at most '
                f'{random["max_relative_energy_drift"]:.1e} and {random["max_relative_cross_helicity_drift"]:.1e}.')]
    count = len(field["pictures"])
    fig, axes = plt.subplots(2, count, figsize=(3 * count, 6.2), squeeze=False)
    top = max(max(max(r) for r in p["density"]) for run in (field, plain) for p in run["pictures"])
    for row, run in enumerate((field, plain)):
        for ax, picture in zip(axes[row], run["pictures"]):
            ax.imshow(picture["density"], origin="lower", extent=run["extent"], cmap="magma", vmin=0, vmax=top)
            ax.set_title(f't = {picture["time"]:.2f}, B0 = {run["magnetic_strength"]:g}', fontsize=9)
            ax.set_xticks([])
            ax.set_yticks([])
    figures.append((save(fig, folder, "mhd_rotor"),
                    "The dye across the rotor: with the field (top) it turns, is braked by the wound-up field "
                    "lines and swings back; without a field (bottom) it winds into a spiral (seed Fig. 6.18)."))
    return figures


def draw_coefficients(data, folder):
    counts = sorted({r["modes"] for r in data["runs"]})
    colours = dict(zip(counts, ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]))
    fig, axes = plt.subplots(1, 3, figsize=(16, 4))
    for run in data["runs"]:
        style = "-" if run["coefficients"] == "ours" else "--"
        label = f'{run["modes"]} modes, {"ours" if run["coefficients"] == "ours" else "grid-evaluated"}'
        axes[0].plot(data["time"], run["relative_l2"], style, color=colours[run["modes"]], label=label)
        axes[1].plot(data["time"], run["relative_linf"], style, color=colours[run["modes"]], label=label)
        e0 = run["energy"][0]
        axes[2].plot(data["time"], [e / e0 - 1 for e in run["energy"]], style, color=colours[run["modes"]],
                     label=label)
    for ax, title in zip(axes, ["relative L2 error against the full run", "relative L∞ error against the full run",
                                "E(t) / E(0) − 1"]):
        ax.set_xlabel("time")
        ax.set_title(title, fontsize=10)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7)
    scene = data["scene"]
    means = ", ".join(f'{r["modes"]} {r["coefficients"]} {r["mean_relative_l2"]:.3f}' for r in data["runs"])
    asym = ", ".join(f'{a["antisymmetry_error"]:.2f} at {a["modes"]}' for a in data["grid_antisymmetry"])
    return [(save(fig, folder, "coefficients"),
             f'Two co-rotating vortices in the unit disk at {scene["resolution"]}²: every divergence-free mode '
             f'({scene["full_modes"]}) is the full simulation; the first N modes with our exactly antisymmetric '
             f'coefficients (solid) and with the advection −⟨Ψk, (Ψi·∇)Ψj⟩ evaluated on the grid (dashed; '
             f'antisymmetry error {asym}), midpoint rule for all, dt = {scene["dt"]}. Mean relative L2 errors: '
             f'{means}. Ours keep the energy to round-off; the grid-evaluated ones do not.')]


def draw_resolution(data, folder):
    runs = data["runs"]
    colours = ["tab:blue", "tab:green", "tab:red"]
    fig, (path, energy) = plt.subplots(1, 2, figsize=(11, 3.8))
    for run, colour in zip(runs, colours):
        label = f'{run["resolution"]}²'
        path.plot(run["time"], run["centroid_y"], color=colour, label=label)
        energy.plot(run["time"], run["modal_energy"], color=colour, label=label)
    path.set_ylabel("smoke centroid height")
    energy.set_ylabel("modal energy ½|v|²")
    for ax in (path, energy):
        ax.set_xlabel("time")
        ax.legend(fontsize=8)
        ax.grid(True, alpha=0.3)
    figures = [(save(fig, folder, "resolution_paths"),
                "Smoke rising in the unit disk (the default scene, 40 modes) on grids of "
                + ", ".join(f'{r["resolution"]}²' for r in runs) + ": centroid height and modal energy over time. "
                "Largest centroid distance from the finest grid: "
                + ", ".join(f'{r["resolution"]}² {r["max_centroid_distance_to_finest"]:.4f}' for r in runs[:-1])
                + " (disk radius 1).")]
    shots = len(runs[0]["pictures"])
    fig, axes = plt.subplots(1, shots, figsize=(4 * shots, 4.4), squeeze=False)
    extent = data["scene"]["extent"]
    for ax, index in zip(axes[0], range(shots)):
        finest = runs[-1]["pictures"][index]["density"]
        top = max(max(row) for row in finest)
        ax.imshow(finest, origin="lower", extent=extent, cmap="Greys", vmin=0, vmax=top)
        for run, colour in zip(runs, colours):
            picture = run["pictures"][index]["density"]
            ax.contour(picture, levels=[0.25 * top], colors=[colour], origin="lower", extent=extent, linewidths=1.2)
        ax.set_title(f't = {runs[-1]["pictures"][index]["time"]:.2f}: '
                     + ", ".join(f'{r["resolution"]}²' for r in runs), fontsize=9)
        ax.set_xticks([])
        ax.set_yticks([])
    figures.append((save(fig, folder, "resolution_overlay"),
                    "The smoke of the finest grid (grey) with the outline (a quarter of its peak density) of every "
                    "grid drawn over it in the colours above (seed Fig. 6.11)."))
    return figures


def draw_speed(data, folder):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for storage, colour in (("dense", "tab:blue"), ("sparse", "tab:green")):
        rows = [r for r in data["rows"] if r["storage"] == storage]
        modes = [r["modes"] for r in rows]
        ax.loglog(modes, [r["midpoint_seconds"] for r in rows], "o-", color=colour, label=f"ours, {storage}, midpoint")
        ax.loglog(modes, [r["explicit_seconds"] for r in rows], "^:", color=colour, label=f"ours, {storage}, explicit")
        ax.loglog(modes, [r["seed_seconds"] for r in rows], "s--", color=colour, alpha=0.6,
                  label=f"seed §6.4, {storage}")
    ax.set_xlabel("modes")
    ax.set_ylabel("seconds per step")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    rows = "; ".join(f'{r["storage"]} {r["modes"]}: {r["midpoint_seconds"] * 1e3:.2f} ms '
                     f'({r["midpoint_iterations"]:.1f} iterations), {r["speedup"]:.0f}× the seed' for r in data["rows"])
    return [(save(fig, folder, "speed"),
             f'Wall time of one reduced step on the CPU reference, {data["threads"]} thread, against the seed’s '
             f'published figures (an Intel i7 laptop): {rows}.')]


def draw_reduced_vs_full(data, folder):
    plume = data["plume"]
    runs = plume["runs"]
    cmap = plt.get_cmap("viridis")
    fig, axes = plt.subplots(1, 4, figsize=(18, 3.9))
    for index, run in enumerate(runs):
        full = run["modes"] == plume["full_modes"]
        colour = "black" if full else cmap(index / max(1, len(runs) - 1))
        label = f'{run["modes"]} modes' + (" (full)" if full else "")
        axes[0].plot(plume["time"], run["centroid_height"], color=colour, label=label)
        axes[1].plot(plume["time"], run["peak_speed"], color=colour, label=label)
        if not full:
            axes[2].plot(plume["time"], run["relative_l2"], color=colour, label=label)
            axes[2].plot(plume["time"], run["relative_linf"], ":", color=colour)
    reduced = [r for r in runs if r["modes"] != plume["full_modes"]]
    axes[3].semilogx([r["modes"] for r in reduced], [r["rise_fraction_of_full"] for r in reduced], "o-")
    axes[3].axhline(1.0, color="black", lw=1)
    for ax, title in zip(axes, ["smoke centroid height", "peak speed", "relative L2 (solid), L∞ (dotted) error",
                                "centroid rise / the full run's"]):
        ax.set_title(title, fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.set_xlabel("modes" if ax is axes[3] else "time")
    axes[0].legend(fontsize=7)
    figures = [(save(fig, folder, "reduced_vs_full_plume"),
             f'A hot disk at the floor of a closed box, {plume["resolution"]}² cells: the full run keeps every '
             f'divergence-free mode of the grid ({plume["full_modes"]}), the reduced runs its leading N. The rise '
             f'converges to the full run as N grows; with few modes the buoyancy is spread over large modes and '
             f'the smoke rises slowly (the projection of a force narrower than the modes).')]
    ball = data["plume_3d"]
    manta = ball.get("mantaflow", {"not_run": "this results.json has no outside check"})
    fig, axes = plt.subplots(1, 4, figsize=(20, 4))
    modes = [r["modes"] for r in ball["runs"]]
    axes[0].semilogx(modes, [r["response_peak_fraction"] for r in ball["runs"]], "o-", label="peak upward speed")
    axes[0].semilogx(modes, [r["response_rise_fraction"] for r in ball["runs"]], "s-",
                     label="mean upward speed over the hot cells")
    axes[0].axhline(1.0, color="black", lw=1)
    axes[0].set_xlabel("modes")
    axes[0].set_title("first step's response / the full grid's P(g)", fontsize=10)
    axes[0].legend(fontsize=7)
    for index, run in enumerate(ball["runs"]):
        colour = cmap(index / max(1, len(ball["runs"]) - 1))
        axes[1].plot(run["time"], run["centroid_height"], color=colour, label=f'{run["modes"]} modes')
        axes[2].plot(run["time"], run["peak_speed"], color=colour, label=f'{run["modes"]} modes')
    if "not_run" in manta:
        axes[3].text(0.5, 0.5, "Blender's Mantaflow was not run:\n" + manta["not_run"], ha="center",
                     va="center", wrap=True, fontsize=9, transform=axes[3].transAxes)
        axes[3].set_xticks([])
        axes[3].set_yticks([])
        outside = f'Blender’s Mantaflow, the outside check, was not run: {manta["not_run"]}.'
    else:
        tag = f'Mantaflow {manta["resolution"]}³ (full grid)'
        axes[1].plot(manta["time"], manta["centroid_height"], "k--", lw=2, label=tag)
        axes[2].plot(manta["time"], manta["peak_speed"], "k--", lw=2, label=tag)
        manta_rise = manta["centroid_height"][-1] - manta["centroid_height"][0]
        rise = [(r["centroid_height"][-1] - r["centroid_height"][0]) / manta_rise for r in ball["runs"]]
        peak = [r["peak_speed"][-1] / manta["peak_speed"][-1] for r in ball["runs"]]
        axes[3].semilogx(modes, rise, "o-", label="centroid rise")
        axes[3].semilogx(modes, peak, "s-", label="peak speed")
        axes[3].axhline(1.0, color="black", lw=1, ls="--")
        axes[3].set_xlabel("modes")
        axes[3].legend(fontsize=7)
        last = ball["runs"][-1]
        outside = (f'Dashed: {manta["solver"]} on the same scene ({manta["resolution"]}³, one step of '
                   f'{ball["dt"]:g} per frame, vorticity confinement, dissolve and noise off; its heat is set '
                   f'inside the ball rather than added, see tools/validate/mantaflow_plume.py): centroid '
                   f'{manta["centroid_height"][0]:.3f} → {manta["centroid_height"][-1]:.3f}, peak speed '
                   f'{manta["peak_speed"][-1]:.3f} at t = {manta["time"][-1]:g}; {last["modes"]} modes '
                   f'{last["centroid_height"][0]:.3f} → {last["centroid_height"][-1]:.3f}, '
                   f'{last["peak_speed"][-1]:.3f} (right: each run at t = {manta["time"][-1]:g} as a fraction '
                   f'of Mantaflow’s).')
    axes[3].set_title("at the end, / Mantaflow's", fontsize=10)
    axes[1].set_title("smoke centroid height", fontsize=10)
    axes[2].set_title("peak speed", fontsize=10)
    axes[1].legend(fontsize=7)
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
    for ax in axes[1:3]:
        ax.set_xlabel("time")
    full = ball["full_response"]
    figures.append((save(fig, folder, "reduced_vs_full_ball"),
                    f'The hot ball of a closed {ball["resolution"]}³ box (r = 0.08 at the floor, buoyancy 1) with '
                    f'closed-form bases of {modes[0]} … {modes[-1]} modes. Left: one step’s response to the ball’s '
                    f'buoyancy, dt·P_N(g), as a fraction of the full grid’s dt·P(g) (a pressure solve; peak '
                    f'{full["peak"]:.3f}, mean {full["mean_rise"]:.3f} per unit force): few modes spread the force '
                    f'over large modes, hence the slow rise of a 200-mode run. Middle: the runs, the '
                    f'source heating from t = 0. ' + outside))
    figures += draw_periodic(data["periodic"], folder)
    return figures


def draw_periodic(periodic, folder):
    runs = periodic["runs"]
    cmap = plt.get_cmap("viridis")
    fig, axes = plt.subplots(1, 3, figsize=(15, 3.9))
    for index, run in enumerate(runs):
        colour = cmap(index / max(1, len(runs) - 1))
        axes[0].semilogy(periodic["time"], run["relative_l2"], color=colour, label=f'{run["modes"]} modes')
        axes[0].semilogy(periodic["time"], run["relative_linf"], ":", color=colour)
        axes[2].plot(periodic["time"], [e / run["energy"][0] - 1 for e in run["energy"]], color=colour,
                     label=f'{run["modes"]} modes')
    modes = [r["modes"] for r in runs]
    axes[1].loglog(modes, [r["relative_l2"][-1] for r in runs], "o-", label="L2")
    axes[1].loglog(modes, [r["relative_linf"][-1] for r in runs], "s:", label="L∞")
    full_energy = periodic["full_energy"]
    axes[2].plot(periodic["time"], [e / full_energy[0] - 1 for e in full_energy], color="black", label="full spectrum")
    for ax, title, xlabel in zip(axes, ["relative L2 (solid), L∞ (dotted) error against the full spectrum",
                                        f'error at t = {periodic["time"][-1]:g}', "energy change, E(t) / E(0) − 1"],
                                 ["time", "modes", "time"]):
        ax.set_title(title, fontsize=10)
        ax.set_xlabel(xlabel)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    axes[1].legend(fontsize=7)
    axes[2].legend(fontsize=7)
    figures = [(save(fig, folder, "reduced_vs_full_periodic"),
                f'A band-limited flow on the torus [0, 2π)², {periodic["resolution"]}² cells ({periodic["initial"]}, RMS face velocity {periodic["rms_speed"]:g}), '
                f'advanced by reduced runs of N closed-form torus modes and by the {periodic["full"]} (seed Fig. 6.12). '
                f'The runs leave the full one as energy reaches scales they do not hold; the error falls as N grows.')]
    pictures = [(f'{r["modes"]} modes', r["vorticity"], r.get("markers")) for r in runs]
    pictures.append(("full spectrum", periodic["full_vorticity"], periodic.get("full_markers")))
    side = int(round(len(periodic["full_vorticity"]) ** 0.5))
    limit = max(abs(v) for v in periodic["full_vorticity"])
    length = 2 * math.pi
    fig, axes = plt.subplots(1, len(pictures), figsize=(2.6 * len(pictures), 2.8))
    for ax, (title, values, markers) in zip(axes, pictures):
        grid = [values[row * side:(row + 1) * side] for row in range(side)]
        ax.imshow(grid, origin="lower", cmap="gray", vmin=-limit, vmax=limit, extent=[0, length, 0, length])
        for points, colour in zip(markers or [], ("tab:blue", "tab:red")):
            ax.scatter([p[0] for p in points], [p[1] for p in points], s=0.4, color=colour, linewidths=0)
        ax.set_xlim(0, length)
        ax.set_ylim(0, length)
        ax.set_title(title, fontsize=9)
        ax.set_xticks([])
        ax.set_yticks([])
    start = periodic.get("markers_start")
    markers = (f' The seed’s fluid markers, two disks of radius {marker_radius(start):.2g} left and right of the '
               f'centre at t = 0, carried by each run’s flow, are drawn in blue and red.' if start else '')
    figures.append((save(fig, folder, "reduced_vs_full_periodic_vorticity"),
                    f'Vorticity at t = {periodic["time"][-1]:g} of the same runs (grey scale, light positive, '
                    f'one scale for all, the full run\'s extremes): the fewest modes miss the thin filaments and '
                    f'place the vortices differently.' + markers))
    return figures


def marker_radius(disks):
    """The radius of the first marker disk at the start (its points' largest distance from their mean)."""
    points = disks[0]
    cx = sum(p[0] for p in points) / len(points)
    cy = sum(p[1] for p in points) / len(points)
    return max(math.hypot(p[0] - cx, p[1] - cy) for p in points)


def draw_lans_alpha(data, folder):
    scene = data["scene"]
    runs = data["runs"]
    fig, (spectrum, flux, series) = plt.subplots(1, 3, figsize=(16, 4.6))
    shades = ["tab:orange", "tab:red", "darkred"][-len(runs):], ["tab:cyan", "tab:blue", "navy"][-len(runs):]
    for run, ns_colour, alpha_colour in zip(runs, *shades):
        for key, colour, style, name in (("navier_stokes", ns_colour, "o-", "NS"),
                                         ("lans_alpha", alpha_colour, "s--", f'LANS-α (α = {run["alpha"]:.2f})')):
            model = run[key]
            spectrum.loglog(run["kappa"], model["energy"], style, color=colour, ms=3, lw=1,
                            label=f'{name}, {run["modes"]} modes: slope {model["inertial_slope"]:.2f} '
                                  f'± {model["inertial_slope_error"]:.2f} on κ {model["inertial_range"][0]}–'
                                  f'{model["inertial_range"][1]}')
            flux.semilogx(run["kappa"], [f / model["injection_mean"] for f in model["flux"]], style, color=colour,
                          ms=3, lw=1, label=f'{name}, {run["modes"]} modes')
    largest = runs[-1]
    lo, hi = data["inertial_range"]
    anchor = largest["navier_stokes"]["energy"][lo - 1]
    k = [lo + 0.1 * i for i in range(int(10 * (hi - lo)) + 1)]
    spectrum.loglog(k, [1.5 * anchor * (x / lo) ** (-5.0 / 3.0) for x in k], "k-", lw=2,
                    label="κ^(−5/3) over the inertial range")
    for ax in (spectrum, flux):
        ax.axvspan(lo - 0.3, hi + 0.3, color="grey", alpha=0.12, lw=0)
        ax.set_xticks(largest["kappa"])
        ax.set_xticklabels([f"{x:g}" for x in largest["kappa"]])
        ax.minorticks_off()
    spectrum.set_xlabel("κ (shells of width 1; the last, cut by the truncation, left out)")
    spectrum.set_ylabel(f'E(κ), averaged over t = {scene["averaged_from"]:g} … {scene["duration"]:g}')
    flux.axhline(0.5, color="grey", lw=1, ls=":")
    flux.set_xlabel("κ")
    flux.set_ylabel("energy flux Π(κ) across κ / injection rate")
    for key, colour in (("navier_stokes", "darkred"), ("lans_alpha", "navy")):
        model = largest[key]
        series.plot(model["time"], model["total_energy"], color=colour, lw=1,
                    label=f'{"NS" if key == "navier_stokes" else "LANS-α"} energy')
        series.plot(model["time"], model["dissipation"], color=colour, lw=1, ls="--",
                    label=f'{"NS" if key == "navier_stokes" else "LANS-α"} dissipation rate')
    series.axvline(scene["averaged_from"], color="grey", lw=1)
    series.set_xlabel(f'time ({largest["modes"]} modes)')
    series.set_ylabel("energy (conserved form) and its dissipation rate")
    for ax in (spectrum, flux, series):
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    return [(save(fig, folder, "lans_alpha"),
             f'Forced turbulence on the torus [0, 2π)³ ({scene["resolution"]}³, closed-form bases of '
             f'{", ".join(str(r["modes"]) for r in runs)} modes), the modes with |k| < 2 held at fixed amplitudes '
             f'([forcing]), ν and α chosen per basis (κ_max η ≈ 1, 1/α at half κ_max): the average energy spectrum '
             f'(seed Fig. 6.9) with κ^(−5/3) over the Navier–Stokes inertial range of the largest basis (where the '
             f'flux carries at least half the injected energy; shaded), the energy flux across κ from the structural '
             f'coefficients, and the largest runs\' energy and dissipation over time (the average from the grey '
             f'line on).')]


def draw_wake(data, folder):
    scene = data["scene"]
    fig, (by_modes, by_re, probe) = plt.subplots(1, 3, figsize=(15, 4.2))
    colours = {"re_100": "tab:blue", "re_150": "tab:red"}
    for key, colour in colours.items():
        series = data[key]
        modes = [run["modes"] for run in series["runs"]]
        strouhal = [run["strouhal"] for run in series["runs"]]
        by_modes.plot(modes, strouhal, "o-", color=colour, label=f'Re {series["re"]:g}')
        by_modes.axhline(series["roshko"], color=colour, ls="--", lw=1)
        by_modes.axhspan(0.8 * series["roshko"], 1.2 * series["roshko"], color=colour, alpha=0.08)
        by_re.plot([series["re"]], [strouhal[-1]], "o", color=colour,
                   label=f'Re {series["re"]:g}, {modes[-1]} modes: St {strouhal[-1]:.3f}')
        last = series["runs"][-1]
        probe.plot(last["time"], last["probe"], color=colour, lw=0.8, label=f'Re {series["re"]:g}')
    res = [50 + 2 * i for i in range(76)]
    by_re.plot(res, [0.212 * (1 - 21.2 / r) for r in res], "k-", label="Roshko: 0.212 (1 − 21.2/Re)")
    by_re.fill_between(res, [0.8 * 0.212 * (1 - 21.2 / r) for r in res],
                       [1.2 * 0.212 * (1 - 21.2 / r) for r in res], color="grey", alpha=0.15, label="± 20%")
    by_modes.set_xscale("log")
    by_modes.set_xlabel("velocity modes")
    by_modes.set_ylabel("Strouhal number f D / U (dashed: Roshko; band: ± 20%)")
    by_re.set_xlabel("Re = U D / ν")
    by_re.set_ylabel("Strouhal number")
    probe.set_xlabel("time")
    probe.set_ylabel("transverse velocity two diameters behind")
    probe.axvline(scene["measured_from"], color="grey", lw=1)
    for ax in (by_modes, by_re, probe):
        ax.legend(fontsize=8)
        ax.grid(True, alpha=0.3)
    return [(save(fig, folder, "wake"),
             f'A cylinder of diameter {scene["diameter"]} in a wind of {scene["wind"]} through a closed-form box '
             f'{scene["box"]} ({scene["resolution"][0]} × {scene["resolution"][1]} cells), a still ball obstacle: '
             f'the Strouhal number of its wake from the transverse velocity two diameters behind it (zero crossings '
             f'after t = {scene["measured_from"]:g}), against the number of modes and Roshko\'s fit.')]


DRAWERS = {
    "convergence": draw_convergence,
    "integrators": draw_integrators,
    "mhd": draw_mhd,
    "coefficients": draw_coefficients,
    "resolution": draw_resolution,
    "speed": draw_speed,
    "reduced_vs_full": draw_reduced_vs_full,
    "lans_alpha": draw_lans_alpha,
    "wake": draw_wake,
}


def embedded(path):
    with open(path, "rb") as f:
        return "data:image/png;base64," + base64.b64encode(f.read()).decode("ascii")


def headline_row(key, study):
    h = study.get("headline", {})
    verdict = "met" if h.get("met") else "NOT met"
    return (f"<tr><td><a href='#{key}'>{html.escape(key)}</a></td><td>{html.escape(h.get('name', ''))}</td>"
            f"<td>{h.get('value', float('nan')):.4g}</td><td>{html.escape(h.get('expectation', ''))}</td>"
            f"<td class='{'ok' if h.get('met') else 'bad'}'>{verdict}</td>"
            f"<td>{study.get('seconds', 0):.1f} s</td></tr>")


def main():
    if sys.argv[1:] == ["--check"]:
        return 0
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    folder = sys.argv[1]
    with open(os.path.join(folder, "results.json"), encoding="utf-8") as f:
        results = json.load(f)
    figures = os.path.join(folder, "figures")
    try:
        os.makedirs(figures, exist_ok=True)
    except OSError as e:
        raise WriteFailed(f"cannot create {figures}: {e.strerror or e}") from e
    studies = results["studies"]
    parts = [
        "<!DOCTYPE html><html><head><meta charset='utf-8'><title>modeflow validate</title><style>"
        "body{font-family:sans-serif;max-width:1150px;margin:2em auto;color:#222}"
        "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:4px 8px;text-align:left}"
        ".ok{color:#070}.bad{color:#b00;font-weight:bold}img{max-width:100%}figure{margin:1em 0}"
        "figcaption{font-size:90%;color:#444}</style></head><body>",
        f"<h1>modeflow validate{' (quick)' if results.get('quick') else ''}</h1>",
        f"<p>modeflow {html.escape(results.get('modeflow_version', '?'))}, "
        f"{results.get('seconds', 0):.0f} s in all. The numbers of every figure are in results.json.</p>",
        "<table><tr><th>study</th><th>headline</th><th>value</th><th>expectation</th><th></th><th>time</th></tr>",
    ]
    parts += [headline_row(key, study) for key, study in studies.items()]
    parts.append("</table>")
    for key, study in studies.items():
        parts.append(f"<h2 id='{key}'>{html.escape(key)}</h2><p>{html.escape(study.get('title', ''))}</p>")
        for note in study.get("notes", []):
            parts.append(f"<p>{html.escape(note)}</p>")
        drawer = DRAWERS.get(key)
        if drawer is None:
            parts.append("<p>(no figure for this study)</p>")
            continue
        for path, caption in drawer(study["data"], figures):
            parts.append(f"<figure><img src='{embedded(path)}' alt='{html.escape(key)}'>"
                         f"<figcaption>{html.escape(caption)}</figcaption></figure>")
    parts.append("</body></html>")
    def write(partial):
        with open(partial, "w", encoding="utf-8") as f:
            f.write("\n".join(parts))

    write_atomically(os.path.join(folder, "report.html"), write)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except WriteFailed as e:
        # modeflow validate shows this line as its error.
        print(f"report.py: {e}", file=sys.stderr)
        sys.exit(4)
