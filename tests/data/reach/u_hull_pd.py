# U_i (omega_box) widths of examples/conreach_pd.toml against the hull of 400 sampled trajectories
# (SciPy, rtol 1e-10) over every [t_i, t_{i+1}] (docs/reach.md, "Coupled metrics", U_i).
# Usage: /usr/bin/python3 tests/data/reach/u_hull_pd.py DIR/reach.json [...]
import json, sys, numpy as np
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation as Rot
J = np.diag([1.0, 2.0, 3.0]); kp, kd = 2.0, 3.0
Rg = Rot.from_rotvec([0, 0, np.radians(20)]).as_matrix()
def hat(w): return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
def f(t, y):
    R = y[:9].reshape(3, 3); w = y[9:]
    E = R.T @ Rg; sk = 0.5 * (E - E.T); v = np.array([sk[2, 1], sk[0, 2], sk[1, 0]])
    wd = np.linalg.solve(J, -np.cross(w, J @ w) + kp * v - kd * w)
    return np.concatenate([(R @ hat(w)).ravel(), wd])
rng = np.random.default_rng(1)
w0 = np.array([0.1, -0.05, 0.05]); a = b = 0.05
ts = np.linspace(0, 2, 401)
W = []
for k in range(400):
    u = rng.normal(size=3); u /= np.linalg.norm(u); v = rng.normal(size=3); v /= np.linalg.norm(v)
    if k % 2: u *= rng.uniform() ** (1 / 3); v *= rng.uniform() ** (1 / 3)
    R0 = Rot.from_rotvec(a * u).as_matrix()
    sol = solve_ivp(f, (0, 2), np.concatenate([R0.ravel(), w0 + b * v]), t_eval=ts, rtol=1e-10, atol=1e-12)
    W.append(sol.y[9:].T)
W = np.array(W)  # samples x times x 3
for path in sys.argv[1:]:
    j = json.load(open(path))
    ratios = []
    for s in j["steps"]:
        m = (ts >= s["t"] - 1e-12) & (ts <= s["t_end"] + 1e-12)
        hull = W[:, m, :].max(axis=(0, 1)) - W[:, m, :].min(axis=(0, 1))
        box = np.array(s["omega_box"]["upper"]) - np.array(s["omega_box"]["lower"])
        ratios.append(box / hull)
    ratios = np.array(ratios)
    print(path, j["metric"], "U_i width / sampled hull: min %.1f max %.1f; last step %s" % (ratios.min(), ratios.max(), np.round(ratios[-1], 1)))
