"""A finished Chute run of the study and what the study's figures read from it: speeds, the first impact, the
rebound, the runout, the decelerations after contact, the force split and the wet restitution. Every number comes
from the run's own files (body_<body>.csv, contacts.csv, lumped_<body>.csv, case.yaml, wall_seconds.txt)."""
import math
import os
import sys

import numpy as np
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from plot_run import read_csv  # noqa: E402


def read_case(path):
    """The case a run ran: its results folder's case.yaml with the command line's --set overrides applied (the
    solver lists them as comments at the end: "#   key.path=value")."""
    text = open(path).read()
    case = yaml.safe_load(text)
    marker = "# Overrides given on the command line"
    if marker in text:
        for line in text[text.index(marker):].splitlines()[1:]:
            if not line.startswith("#   ") or "=" not in line:
                continue
            key, value = line[4:].split("=", 1)
            node = case
            *parents, last = key.strip().split(".")
            for name in parents:
                node = node.setdefault(name, {})
            node[last] = yaml.safe_load(value)
    return case


class Run:
    def __init__(self, label, folder, body="block"):
        self.label, self.folder, self.body = label, folder, body
        self.series = read_csv(os.path.join(folder, f"body_{body}.csv"))
        self.case = read_case(os.path.join(folder, "case.yaml"))
        self.gravity = np.array(self.case.get("gravity", [0.0, -9.81]), dtype=float)
        self.down = self.gravity / np.linalg.norm(self.gravity)
        self.across = np.array([-self.down[1], self.down[0]])  # horizontal in the real frame, towards +x at 0
        if self.across[0] < 0:
            self.across = -self.across
        path = os.path.join(folder, "contacts.csv")
        impacts = read_csv(path) if os.path.exists(path) and os.path.getsize(path) > 0 else {}
        # Every contact, those where the block comes to rest included (a landing ends a runout all the same).
        self.impacts = impacts if impacts and len(impacts["t"]) else None
        self.lumped_table = read_csv(os.path.join(folder, f"lumped_{body}.csv"))
        wall = os.path.join(folder, "wall_seconds.txt")
        self.wall = float(open(wall).read()) if os.path.exists(wall) else math.nan
        carrier = self.case["bodies"][body].get("carrier")
        self.mode = "body-fitted" if carrier == "body_fitted" else "immersed"

    # --- series ---------------------------------------------------------------------------------------------------
    @property
    def t(self):
        return self.series["t"]

    def velocity(self):
        return np.stack([self.series["u"], self.series["v"]], axis=1)

    def fall_speed(self):
        """Speed along gravity (positive down)."""
        return self.velocity() @ self.down

    def height(self):
        """The centre's height against gravity, from its start."""
        p = np.stack([self.series["x"], self.series["y"]], axis=1)
        return -(p - p[0]) @ self.down

    def force(self, kind):
        """A force series along gravity's up direction (N): forcing (the total hydrodynamic force (a)), pressure,
        viscous, turbulent, surface."""
        return -(self.series[f"fx_{kind}"] * self.down[0] + self.series[f"fy_{kind}"] * self.down[1])

    def at(self, time, values):
        return float(np.interp(time, self.t, values))

    # --- the free fall --------------------------------------------------------------------------------------------
    def first_impact_time(self):
        return float(self.impacts["t"][0]) if self.impacts is not None else math.inf

    def terminal_speed(self, start=1.5, end=math.inf):
        """Mean fall speed over [start, end] before any impact (the validation tests' window)."""
        window = (self.t >= start) & (self.t <= min(end, self.first_impact_time()))
        return float(self.fall_speed()[window].mean()) if window.any() else math.nan

    def time_to_95(self, terminal):
        reached = np.nonzero(self.fall_speed() >= 0.95 * terminal)[0]
        return float(self.t[reached[0]]) if len(reached) else math.nan

    def fall_to_95(self, terminal):
        """Distance fallen when the speed first reaches 95 % of the terminal speed."""
        t95 = self.time_to_95(terminal)
        return -self.at(t95, self.height()) if math.isfinite(t95) else math.nan

    # --- impacts --------------------------------------------------------------------------------------------------
    def impact_speed(self, k=0):
        """Speed along gravity just before impact k (m/s)."""
        if self.impacts is None or len(self.impacts["t"]) <= k:
            return math.nan
        return float(np.array([self.impacts["u_before"][k], self.impacts["v_before"][k]]) @ self.down)

    def first_flight(self):
        """The samples from the first impact to the next contact (or the run's end); None without an impact."""
        if self.impacts is None:
            return None
        t1 = float(self.impacts["t"][1]) if len(self.impacts["t"]) > 1 else self.t[-1]
        return (self.t >= self.first_impact_time()) & (self.t <= t1)

    def rebound_height(self):
        """Rise of the centre against gravity between the first impact and the top of the flight that follows."""
        flight = self.first_flight()
        if flight is None or not flight.any():
            return math.nan
        h = self.height()
        return float(h[flight].max() - self.at(self.first_impact_time(), h))

    def deceleration_after_impact(self, span=0.01):
        """Mean deceleration over the first `span` seconds after the first impact: the drop of the rising speed
        against gravity, per second (the study: above 20 m/s^2 just after contact)."""
        if self.impacts is None:
            return math.nan
        t0 = self.first_impact_time()
        rise = -self.fall_speed()
        after = np.nonzero(self.t > t0)[0]
        if not len(after):
            return math.nan
        start = after[0]
        return (rise[start] - self.at(self.t[start] + span, rise)) / span

    def mean_deceleration_rising(self):
        """Mean deceleration (m/s^2) over the upward movement after the first impact: the speed the block leaves
        the bed with over the time it takes to stop rising (the study: more than g during all of it)."""
        if self.impacts is None:
            return math.nan
        rise = -self.fall_speed()
        after = np.nonzero(self.t > self.first_impact_time())[0]
        if len(after) < 2 or rise[after[0]] <= 0:
            return math.nan
        k = end = after[0]
        while end + 1 < len(rise) and rise[end + 1] > 0:
            end += 1
        return float(rise[k] / (self.t[end + 1] - self.t[k])) if end + 1 < len(rise) else math.nan

    def runout(self):
        """Horizontal distance (across gravity, the real frame's horizontal) between the first two impacts."""
        if self.impacts is None or len(self.impacts["t"]) < 2:
            return math.nan
        d = np.array([self.impacts["x_centre"][1] - self.impacts["x_centre"][0],
                      self.impacts["y_centre"][1] - self.impacts["y_centre"][0]])
        return float(abs(d @ self.across))

    def wet_restitution(self):
        """(normal, tangential) restitution of the first impact with the water's share included: the speed with
        which the block leaves the surface over the speed it arrived with (contacts.csv's wet columns), and the
        normal one a dry model would need to rise as far from the surface (sqrt(2 g_n h_n) over the impact's normal
        speed, h_n the rise normal to the surface and g_n gravity's component along it)."""
        if self.impacts is None:
            return math.nan, math.nan, math.nan
        normal_in = abs(self.impacts["v_before"][0])  # the contact planes of the study's scenarios face +y
        flight = self.first_flight()
        y = self.series["y"]
        rise = float(y[flight].max() - self.at(self.first_impact_time(), y)) if flight.any() else 0.0
        by_height = math.sqrt(2 * abs(self.gravity[1]) * max(rise, 0.0)) / normal_in
        return (float(self.impacts["wet_normal_restitution"][0]),
                float(self.impacts["wet_tangential_restitution"][0]), by_height)

    # --- forces ---------------------------------------------------------------------------------------------------
    def force_split(self, start, end):
        """Mean pressure, viscous and turbulent forces along the mean total force (a) over [start, end] (N), and
        the total (a): what the study's time series are made of."""
        window = (self.t >= start) & (self.t <= end)
        if not window.any():
            return {k: math.nan for k in ("forcing", "pressure", "viscous", "turbulent")}
        total = np.array([self.series["fx_forcing"][window].mean(), self.series["fy_forcing"][window].mean()])
        along = total / max(np.linalg.norm(total), 1e-300)
        return {k: float((self.series[f"fx_{k}"][window] * along[0] + self.series[f"fy_{k}"][window] * along[1]).mean())
                for k in ("forcing", "pressure", "viscous", "turbulent")}

    # --- the lumped models of the same release --------------------------------------------------------------------
    def lumped(self, model):
        """model 0: dry (no fluid); 1: Beranger et al. (1998), C_D 2, C_a 0.5. Time, height, fall speed."""
        m = self.lumped_table
        keep = m["model"] == model
        p = np.stack([m["x"][keep], m["y"][keep]], axis=1)
        v = np.stack([m["u"][keep], m["v"][keep]], axis=1)
        return m["t"][keep], -(p - p[0]) @ self.down, v @ self.down, p


def read_runs(scenario_out):
    """The runs a scenario's `run` script listed (runs.txt: label, folder, wall seconds), by label."""
    runs = {}
    with open(os.path.join(scenario_out, "runs.txt")) as f:
        for line in f:
            label, folder, _ = line.rstrip("\n").split("\t")
            runs[label] = Run(label, folder)
    return runs
