"""attiguard.plot campaign: histograms and margin-vs-parameter scatter from runs.csv."""

import json

import pytest

pytest.importorskip("matplotlib")

from attiguard.plot.__main__ import main  # noqa: E402

HEADER = "run,seed,attempts,status,reason,control.kp,violation,min_pointing_margin,max_torque_norm"
ROWS = [
    "0,11,1,ok,,4.5,0,0.05,1.2",
    "1,12,2,ok,,5.5,1,-0.01,1.9",
    "2,13,1,failed,\"integrator: non-finite state, t = 1\",5.0,,,",
    "3,14,1,ok,,4.9,0,0.07,1.4",
]


def test_campaign_plots_are_written(tmp_path, capsys):
    (tmp_path / "runs.csv").write_text(HEADER + "\n" + "\n".join(ROWS) + "\n")
    (tmp_path / "campaign.json").write_text(json.dumps({"scenario": "t.toml", "violations": 1}))
    assert main(["campaign", str(tmp_path)]) == 0
    written = capsys.readouterr().out.split()
    assert [p.rsplit("/", 1)[-1] for p in written] == ["campaign_histograms.png",
                                                        "campaign_scatter.png"]
    for p in written:
        assert (tmp_path / p.rsplit("/", 1)[-1]).stat().st_size > 1000


def test_campaign_without_runs_is_a_usage_error(tmp_path):
    assert main(["campaign", str(tmp_path)]) == 2
