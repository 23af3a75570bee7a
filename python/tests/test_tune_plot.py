"""attiguard.plot tune: convergence time against each tuned key from tune.json."""

import json

import pytest

pytest.importorskip("matplotlib")

from attiguard.plot.__main__ import main  # noqa: E402


def _point(i, kp, t, admissible=True, violations=0):
    return {"index": i, "phase": "sample", "values": {"control.kp": kp, "erg.kappa": 1.0 + i},
            "status": "ok", "outcome": "converged" if t is not None else "stalled", "reason": "",
            "violations": violations, "admissible": admissible, "convergence_time": t,
            "convergence_time_over_bang_bang": None if t is None else t / 10.0}


def test_tune_tradeoff_plot_is_written(tmp_path, capsys):
    points = [_point(0, 1.0, 50.0), _point(1, 2.0, 30.0), _point(2, 4.0, None, False),
              _point(3, 8.0, 20.0, False, 1)]
    data = {"parameters": [{"key": "control.kp", "min": 1, "max": 8}, {"key": "erg.kappa", "min": 1, "max": 4}],
            "points": points, "best": points[1], "evaluated": 4, "admissible": 2,
            "eigenaxis_bang_bang_time": 10.0}
    (tmp_path / "tune.json").write_text(json.dumps(data))
    assert main(["tune", str(tmp_path)]) == 0
    written = capsys.readouterr().out.split()
    assert [p.rsplit("/", 1)[-1] for p in written] == ["tune_tradeoff.png"]
    assert (tmp_path / "tune_tradeoff.png").stat().st_size > 1000


def test_tune_without_tune_json_is_a_usage_error(tmp_path):
    assert main(["tune", str(tmp_path)]) == 2
    (tmp_path / "tune.json").write_text("{}")
    assert main(["tune", str(tmp_path)]) == 2
