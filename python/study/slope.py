"""The study's bounces on 45 and 30 degree slopes (Turmel & Locat 2008, sec. 4.3, Figs. 9 and 10), run as the study
ran them (a horizontal bed under gravity tilted by the slope's angle): the paths in water (both modes) and in air
drawn in the real frame (gravity down, the slope inclined), the runout to the next impact water against air, and,
beyond the study, the same with the rotation free."""
import numpy as np

from bounce import RESTITUTION_HEADER, restitution_rows
from common import SPLIT_HEADER, plt, split_row

COLOURS = {"water_immersed": "tab:blue", "water_body_fitted": "tab:blue", "air_immersed": "tab:red",
           "air_for_body_fitted": "tab:red",
           "water_rotating": "tab:purple", "water_immersed_study_impulse": "tab:green",
           "water_body_fitted_study_impulse": "tab:green"}
LINES = {"water_immersed": "-", "water_body_fitted": "--", "air_immersed": "-", "air_for_body_fitted": "--",
         "water_rotating": "-.",
         "water_immersed_study_impulse": "-", "water_body_fitted_study_impulse": "--"}
NAMES = {"water_immersed": "water, immersed", "water_body_fitted": "water, body-fitted",
         "air_immersed": "air, at the immersed water run's speed at contact",
         "air_for_body_fitted": "air, at the body-fitted water run's speed at contact",
         "water_rotating": "water, rotation free (immersed)",
         "water_immersed_study_impulse": "water, the study's impact treatment, immersed",
         "water_body_fitted_study_impulse": "water, the study's impact treatment, body-fitted"}


def real_frame(run):
    """The centre's path from its first impact, turned so that gravity points down (the bed becomes the slope)."""
    p = np.stack([run.series["x"], run.series["y"]], axis=1)
    t0 = run.first_impact_time()
    origin = np.array([np.interp(t0, run.t, p[:, 0]), np.interp(t0, run.t, p[:, 1])])
    down = run.down
    # Rotation taking `down` to (0, -1).
    c, s = -down[1], -down[0]
    rot = np.array([[c, -s], [s, c]])
    q = (p - origin) @ rot.T
    if rot[0] @ np.array([1.0, 0.0]) < 0:
        q[:, 0] = -q[:, 0]
    return q, rot


def slopes(runs, ref, result):
    for angle in (45, 30):
        one_slope(runs, ref, result, angle)


def one_slope(runs, ref, result, angle):
    here = {k: runs[f"{k}_{angle}"] for k in COLOURS if f"{k}_{angle}" in runs}
    figure_number = 9 if angle == 45 else 10
    fig, ax = plt.subplots(figsize=(8, 6.4))
    reach = [0.0, 0.0]
    for key, r in here.items():
        q, rot = real_frame(r)
        t0 = r.first_impact_time()
        t_end = float(r.impacts["t"][1]) + 0.05 if r.impacts is not None and len(r.impacts["t"]) > 1 else r.t[-1]
        keep = (r.t >= t0 - 0.25) & (r.t <= t_end)
        ax.plot(q[keep, 0], q[keep, 1], LINES[key], color=COLOURS[key], label=NAMES[key])
        reach = [min(reach[0], q[keep, 0].min()), max(reach[1], q[keep, 0].max())]
    # The line the centre meets the slope along (the bed, 0.25 m below the centre at contact), in the real frame.
    r = here["water_immersed"]
    _, rot = real_frame(r)
    along = rot @ np.array([1.0, 0.0])
    if along[0] < 0:
        along = -along
    s = np.array([reach[0] - 0.1, reach[1] + 0.1]) / along[0]
    ax.plot(s * along[0], s * along[1], color="k", lw=0.8, label="the contact line (the slope)")
    ax.set_aspect("equal")
    ax.set_xlabel("horizontal distance from the first impact (m)")
    ax.set_ylabel("height (m)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2)
    ax.set_title(f"Fig. {figure_number}: bouncing on a {angle} degree slope, water against air (Rn = Rt = 0.8)",
                 fontsize=10)
    fig.subplots_adjust(bottom=0.33, top=0.93)
    result.figure(fig, f"fig{figure_number}_slope_{angle}.png", f"Path of the block's centre from 0.25 s before its "
                  f"first impact on the {angle} degree slope to its second, in the real frame.")
    water = {"immersed": here.get("water_immersed"), "body-fitted": here.get("water_body_fitted")}
    # Each mode's water run against the air run released to meet the slope at the same speed (the study's set-up).
    air = {"immersed": here.get("air_immersed"), "body-fitted": here.get("air_for_body_fitted")}
    result.claim(ref[f"arrival_{angle}"], {m: r.impact_speed() for m, r in water.items() if r is not None})
    result.claim(ref[f"runout_ratio_{angle}"], {m: r.runout() / air[m].runout() for m, r in water.items()
                                                if r is not None and air.get(m) is not None})
    studys = {"immersed": here.get("water_immersed_study_impulse"),
              "body-fitted": here.get("water_body_fitted_study_impulse")}
    row = dict(ref[f"runout_ratio_{angle}"])
    row["claim"] += " (with the study's treatment of the impact: contact.water_impulse body)"
    result.claim(row, {m: r.runout() / air[m].runout() for m, r in studys.items()
                       if r is not None and air.get(m) is not None})
    rows = []
    for k, r in here.items():
        against = air["body-fitted" if r.mode == "body-fitted" or k == "air_for_body_fitted" else "immersed"]
        rows.append([NAMES[k], f"{r.impact_speed():.3f}", f"{r.runout():.4f}",
                     f"{r.runout() / against.runout():.3f}" if against is not None else "n/a"])
    result.table(f"{angle} degrees: speed at contact and runout (horizontal distance to the next impact)",
                 ["run", "speed at contact (m/s)", "runout (m)", "over air at the same speed"], rows)
    rotating = here.get("water_rotating")
    if rotating is not None:
        end = float(rotating.impacts["t"][1]) if rotating.impacts is not None and len(rotating.impacts["t"]) > 1 \
            else rotating.t[-1]
        turned = float(np.degrees(np.interp(end, rotating.t, rotating.series["angle"])))
        result.table(f"{angle} degrees with the rotation free (immersed, water; the study had to lock it)",
                     ["runout, locked (m)", "runout, free (m)", "turned by the next impact (degrees)"],
                     [[f"{water['immersed'].runout():.4f}", f"{rotating.runout():.4f}", f"{turned:.1f}"]],
                     topic="rotation free")
    result.table(f"{angle} degree slope: wet restitution of the first impact (the study took the dry 0.8 for both)",
                 RESTITUTION_HEADER, restitution_rows({NAMES[k]: r for k, r in here.items()}), topic="wet restitution")
    rows = [split_row(f"{NAMES[k]}, 0.1 s after the impact",
                      r.force_split(r.first_impact_time(), r.first_impact_time() + 0.1))
            for k, r in here.items() if not k.startswith("air")]
    result.table(f"{angle} degree slope: force split just after the impact", SPLIT_HEADER, rows, topic="force split")
