"""The study's bounces on a horizontal bed (Turmel & Locat 2008, sec. 4.2, Figs. 6 to 8): displacement and
pressure force against time for both blocks in both modes, the decelerations after contact, and the rebound
against air and the Beranger model; beyond the study, contact at the bed, the wet restitution and the grid
convergence of the rebound height."""
import math

import numpy as np

from common import MODES, SPLIT_HEADER, STYLE, finish_axes, plt, split_row
from fall import convergence_levels, mode_runs


def restitution_rows(runs):
    rows = []
    for label, r in runs.items():
        normal, tangential, by_height = r.wet_restitution()
        if math.isnan(normal):
            continue
        rows.append([label, r.mode, f"{r.impact_speed():.3f}", f"{normal:.3f}",
                     "n/a" if math.isnan(tangential) else f"{tangential:.3f}", f"{by_height:.3f}"])
    return rows


RESTITUTION_HEADER = ["run", "mode", "impact speed (m/s)", "normal, leaving the bed (contacts.csv)",
                      "tangential, leaving (contacts.csv)", "dry-equivalent normal: sqrt(2 g h) / arrival"]


def bed(runs, ref, result, figure_number, block):
    base = mode_runs(runs)
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.5, 6.4), sharex=True)
    impact = min(r.first_impact_time() for r in base.values())
    for mode, r in base.items():
        a1.plot(r.t, r.height(), STYLE[mode], label=f"Chute, {mode}")
        a2.plot(r.t, r.force("pressure") / 1000, STYLE[mode], label=f"Chute, {mode}")
    a1.set_ylabel("displacement of the centre (m)")
    a2.set_ylabel("pressure force, upward (kN)")
    a2.set_xlabel("t (s)")
    for a in (a1, a2):
        a.axvline(impact, color="k", lw=0.5, alpha=0.5)
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.suptitle(f"Fig. {figure_number}: the {block} block bouncing on the bed (contact 0.1 m off it, Rn = Rt = 0.8)",
                 fontsize=10)
    result.figure(fig, f"fig{figure_number}_bed.png", f"Displacement and pressure force of the {block} block "
                  "against time in both modes; the vertical line marks the first impact.")
    result.claim(ref["deceleration_after_contact"], {m: r.deceleration_after_impact() for m, r in base.items()})
    result.claim(ref["deceleration_rising"], {m: r.mean_deceleration_rising() for m, r in base.items()})
    rows = [[m, f"{r.impact_speed():.3f}", f"{r.rebound_height():.4f}", f"{r.deceleration_after_impact():.1f}"]
            for m, r in base.items()]
    result.table("The first impact", ["mode", "impact speed (m/s)", "rebound height (m)",
                                       "deceleration, first 0.01 s (m/s^2)"], rows)
    result.table(f"Wet restitution of the {block} block's first impact on the bed (the study took the dry 0.8)",
                 RESTITUTION_HEADER, restitution_rows(base), topic="wet restitution")
    rows = [split_row(f"{m}, 0.1 s after the impact", r.force_split(r.first_impact_time(),
                                                                     r.first_impact_time() + 0.1))
            for m, r in base.items()]
    result.table(f"Force split of the {block} block just after its impact on the bed", SPLIT_HEADER, rows,
                 topic="force split")
    gap = mode_runs(runs, "_gap5mm")
    if gap:
        rows = []
        for m, r in gap.items():
            touched = r.impacts is not None
            rows.append([m, f"{r.impact_speed():.3f}" if touched else "never touches",
                         f"{base[m].impact_speed():.3f}" if m in base else "n/a"])
        result.table(f"The {block} block meeting the bed 5 mm from it instead of 0.1 m (to t = 1.7 s)",
                     ["mode", "impact speed at 5 mm (m/s)", "at 0.1 m (m/s)"], rows,
                     "The water squeezed out between face and bed brakes the block before it touches: resolved by the "
                     "body-fitted layers; the immersed grid cannot resolve a gap of a fraction of its cell.",
                     topic="contact at the bed")
    rows = []
    for mode in MODES:
        levels = convergence_levels(runs, mode)
        if len(levels) == 3:
            rows.append([mode] + [f"{r.rebound_height():.4f}" for _, r in levels])
    if rows:
        result.table(f"Grid convergence of the {block} block's rebound height on the bed (m)",
                     ["mode", "10 cells across", "20 (the study's grid)", "30"], rows, topic="grid convergence")
    elif result.data["quick"]:
        result.note("Grid convergence: not run with --quick.")


def bed_03(runs, ref, result):
    bed(runs, ref, result, 6, "0.3 m")


def bed_1m(runs, ref, result):
    bed(runs, ref, result, 7, "1 m")


def air_beranger(runs, ref, result):
    water = {"immersed": runs["water_immersed"], "body-fitted": runs["water_body_fitted"]}
    air = {"immersed": runs["air_immersed"], "body-fitted": runs["air_body_fitted"]}
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    for mode in MODES:
        ax.plot(water[mode].t, water[mode].height(), STYLE[mode], color="tab:blue", label=f"water, Chute {mode}")
        ax.plot(air[mode].t, air[mode].height(), STYLE[mode], color="tab:red", label=f"air, Chute {mode}")
    t, h, _, _ = water["immersed"].lumped(1)
    ax.plot(t, h, ":", color="tab:green", label="water, Beranger et al. (1998)")
    finish_axes(ax, "t (s)", "displacement of the centre (m)",
                "Fig. 8: the 0.3 m block's bed bounce: Chute in water and air, and the Beranger model")
    result.figure(fig, "fig8_air_beranger.png", "Displacement against time: the CFD in water and in air (both modes) "
                  "and the Beranger lumped model in water (C_D 2, C_a 0.5, the same release and restitution).")
    beranger = beranger_rebound(water["immersed"])
    result.claim(ref["beranger_over_water"], {m: beranger / water[m].rebound_height() for m in MODES}, digits=3)
    result.claim(ref["air_over_water"], {m: air[m].rebound_height() / water[m].rebound_height() for m in MODES})
    study = {m: runs.get(f"water_{m.replace('-', '_')}_study_impulse") for m in MODES}
    study = {m: r for m, r in study.items() if r is not None}
    for key in ("beranger_over_water", "air_over_water"):
        row = dict(ref[key])
        row["claim"] += " (with the study's treatment of the impact: contact.water_impulse body)"
        top = {m: beranger if key == "beranger_over_water" else air[m].rebound_height() for m in study}
        result.claim(row, {m: top[m] / max(r.rebound_height(), 1e-12) for m, r in study.items()})
    rows = [[m, f"{water[m].rebound_height():.4f}",
             f"{study[m].rebound_height():.4f}" if m in study else "n/a", f"{air[m].rebound_height():.4f}",
             f"{beranger:.4f}"] for m in MODES]
    result.table("Rebound heights (m)", ["mode", "water", "water, the study's impact treatment", "air",
                                         "Beranger (water)"], rows)
    if study:
        fig, ax = plt.subplots(figsize=(7.5, 4.0))
        for m, r in study.items():
            ax.plot(r.t, r.height(), STYLE[m], color="tab:green", label=f"water, the study's impact treatment, {m}")
            ax.plot(water[m].t, water[m].height(), STYLE[m], color="tab:blue", label=f"water, Chute's default, {m}")
        t, h, _, _ = water["immersed"].lumped(1)
        ax.plot(t, h, ":", color="k", label="Beranger et al. (1998)")
        impact = water["immersed"].first_impact_time()
        ax.set_xlim(impact - 0.3, water["immersed"].t[-1])
        ground = water["immersed"].at(impact, water["immersed"].height())
        ax.set_ylim(ground - 0.05, ground + 1.5 * max(beranger, water["immersed"].rebound_height()))
        finish_axes(ax, "t (s)", "displacement of the centre (m)",
                    "Fig. 8, close up: the rebound in water with either treatment of the impact", legend_size=7)
        result.figure(fig, "fig8_treatments.png", "The rebound in water with Chute's default treatment of the impact "
                      "(the bed stops the block and the water it carries together) and the study's (the law reverses "
                      "the block alone; its water brakes it after), against the Beranger model.")
    result.table("Wet restitution of the first impact, water and air", RESTITUTION_HEADER,
                 restitution_rows({**{f"water_{m}": water[m] for m in MODES}, **{f"air_{m}": air[m] for m in MODES}}),
                 topic="wet restitution")


def beranger_rebound(run):
    """The Beranger model's rebound: its rise from its first impact (the fall speed turning from down to up) to the
    top of the flight that follows."""
    _, h, v, _ = run.lumped(1)
    turns = np.nonzero((v[:-1] > 0) & (v[1:] <= 0))[0]
    if not len(turns):
        return math.nan
    k = top = turns[0] + 1
    while top + 1 < len(v) and v[top + 1] < 0:
        top += 1
    return float(h[top] - h[k])
