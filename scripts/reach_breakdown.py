#!/usr/bin/env python3
"""Where a ConReach enclosure's looseness comes from (issue 47, docs/reach.md "Tightness breakdown").

  reach_breakdown.py REACH_JSON [REACH_JSON ...]   (needs numpy: /usr/bin/python3)

The attitude tightness of a run, claimed / seen at T (reach.json -> adversarial), is split into
three factors whose product it is exactly:

  cover  = A_0 / a                 the attitude radius A_0 = r_0 / sqrt(lambda_min(Q - S P^-1 S^T))
                                   of the first ball (metric of step 0, radius r_0) over the
                                   initial set's radius a; a single ellipsoid holding the product
                                   set B(a) x B(b) costs at least sqrt(2) when fitted to it;
  rate   = (r_T / r_0) / (s_T / a) how much less the ball's radius shrank over [0, T] than the
                                   true attitude spread (s_T = adversarial attitude_spread);
  metric = (A_T / A_0) / (r_T / r_0) what the change of metric from step 0 to T cost (> 1 when
                                   the metric shrank, M_{i+1} <= M_i).

The first cell's figures (its own nominal); prints a markdown table row per file.
"""

import json
import sys

import numpy as np


def attitude_radius(step, r):
    q, s, p = (np.array(step[k]) for k in ("Q", "S", "P"))
    schur = q - s @ np.linalg.solve(p, s.T)
    return r / np.sqrt(np.linalg.eigvalsh(0.5 * (schur + schur.T))[0])


def breakdown(path):
    d = json.load(open(path))
    steps = d["steps"]
    a = d["initial"]["attitude_radius"]
    r0 = d["initial"]["r0"]
    a0 = attitude_radius(steps[0], r0)
    r_t = steps[-1]["r"]
    a_t = steps[-1]["attitude_radius"]
    adv = d["adversarial"]
    s_t = adv["attitude_spread"]
    cover = a0 / a
    rate = (r_t / r0) / (s_t / a)
    metric = (a_t / a0) / (r_t / r0)
    return {"name": d["name"], "metric_kind": d["metric"], "a": a, "A0": a0, "r0": r0, "rT": r_t,
            "AT": a_t, "sT": s_t, "cover": cover, "rate": rate, "metric": metric,
            "product": cover * rate * metric, "tightness": adv["attitude_tightness"]}


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    print("| run | metric | a | A_0 | cover A_0/a | rate | metric change | product | tightness |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for path in argv[1:]:
        b = breakdown(path)
        print("| %s | %s | %.4g | %.4g | %.2f | %.2f | %.2f | %.2f | %.2f |" % (
            b["name"], b["metric_kind"], b["a"], b["A0"], b["cover"], b["rate"], b["metric"],
            b["product"], b["tightness"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
