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


def _retained_file(path, runs=5, samples=4):
    """A retained.h5 as `attiguard campaign` writes it (docs/campaigns.md, "Retained time series")."""
    h5py = pytest.importorskip("h5py")
    import numpy as np

    t = np.arange(samples) * 0.5
    series = np.array([[0.1 * (k + 1) + 0.01 * s for s in range(samples)] for k in range(runs)])
    with h5py.File(path, "w") as f:
        f["t"] = t
        f["series/margin_0"] = series
        env = np.vstack([series.min(0), series.min(0), np.median(series, 0), series.max(0),
                         series.max(0), np.full(samples, runs)])
        f["envelopes/margin_0"] = env
        f["worst/margin_0"] = np.array([0, 1], dtype=np.int64)


def test_campaign_envelopes_are_drawn_from_the_retained_file(tmp_path, capsys):
    (tmp_path / "runs.csv").write_text(HEADER + "\n" + "\n".join(ROWS) + "\n")
    (tmp_path / "campaign.json").write_text(json.dumps({"scenario": "t.toml", "violations": 1}))
    _retained_file(tmp_path / "retained.h5")
    assert main(["campaign", str(tmp_path)]) == 0
    written = [p.rsplit("/", 1)[-1] for p in capsys.readouterr().out.split()]
    assert written == ["campaign_histograms.png", "campaign_scatter.png", "campaign_envelopes.png"]
    assert (tmp_path / "campaign_envelopes.png").stat().st_size > 1000


def test_campaign_title_is_the_scenario_name_and_every_dispersed_column_gets_a_panel(tmp_path):
    from attiguard.plot import campaign

    names = [f"d{i}" for i in range(14)]  # more dispersed columns than the histogram panels
    header = "run,seed,attempts,status,reason," + ",".join(names) + ",violation,min_pointing_margin"
    rows = [f"{k},1,1,ok,," + ",".join(str(k * (i + 1)) for i in range(14)) + f",0,{0.1 * k}"
            for k in range(4)]
    (tmp_path / "runs.csv").write_text(header + "\n" + "\n".join(rows) + "\n")
    (tmp_path / "campaign.json").write_text(json.dumps({"scenario": "my_campaign.toml"}))
    run = campaign.load(tmp_path)
    assert run.name == "my_campaign"
    assert campaign._dispersed(run) == names


def test_compare_overlays_one_figure_of_several_campaigns(tmp_path, capsys):
    for name, rows in (("robust", ROWS[:1] + ROWS[3:]), ("nominal", ROWS)):
        d = tmp_path / name
        d.mkdir()
        (d / "runs.csv").write_text(HEADER + "\n" + "\n".join(rows) + "\n")
        (d / "campaign.json").write_text(json.dumps({"name": name, "violations": 0 if name == "robust" else 1}))
    out = tmp_path / "cmp.png"
    assert main(["compare", str(tmp_path / "robust"), str(tmp_path / "nominal"), "--out", str(out)]) == 0
    assert capsys.readouterr().out.strip() == str(out)
    assert out.stat().st_size > 1000
    # one directory, or a column runs.csv does not have: usage errors naming the problem
    assert main(["compare", str(tmp_path / "robust"), "--out", str(out)]) == 2
    assert main(["compare", str(tmp_path / "robust"), str(tmp_path / "nominal"), "--figure", "nope",
                 "--out", str(out)]) == 2
    assert "no column 'nope'" in capsys.readouterr().err
