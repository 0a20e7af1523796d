"""esc.run and esc.resume: the directory `esc run` writes with the same arguments, progress
per generation, Ctrl-C leaving a directory that resumes to the uninterrupted run, and the
refusals as esc.Error with their kind."""

import io
import os
import signal

import pandas as pd
import pytest

import esc
from conftest import HOMING, STUDY_SETTINGS, STUDY_TEXT, esc_run, run_esc

# Wall times differ between any two runs; everything else is the same.
TIMES = ["seconds"]


def same_table(a: pd.DataFrame, b: pd.DataFrame):
    pd.testing.assert_frame_equal(a.drop(columns=TIMES + ["directory"]), b.drop(columns=TIMES + ["directory"]),
                                  check_exact=True)


def cli_table(directory) -> pd.DataFrame:
    return pd.read_csv(io.StringIO(run_esc("export", directory, "--format", "csv").stdout),
                       float_precision="round_trip")


def py_run(out, **given):
    """esc.run of the homing script as conftest.esc_run runs it, with `given` in place of those arguments."""
    arguments = {"runs": 1, "generations": 2, "threads": 2, "set": HOMING["settings"], "out": out, **given}
    return esc.run(HOMING["script"], **arguments)


def test_run_writes_what_esc_run_writes(tmp_path):
    cli = esc_run(HOMING["script"], tmp_path / "cli", HOMING["settings"])
    run = py_run(tmp_path / "py")
    assert sorted(os.listdir(tmp_path / "py")) == sorted(os.listdir(cli))
    same_table(run.table(), cli_table(cli))
    assert run.table("usage").equals(esc.open(cli).table("usage"))
    for controller in run.controllers:
        assert (run.best(controller, 1).genome == esc.open(cli).best(controller, 1).genome).all()


def test_progress_is_called_per_generation(tmp_path):
    seen = []
    run = py_run(tmp_path / "py", progress=seen.append)
    assert [(g.controller, g.run, g.generation) for g in seen] == [
        (c, 1, g) for g in range(2) for c in run.controllers] or len(seen) == 2 * len(run.controllers)
    table = run.table()
    for g in seen:
        row = table[(table.controller == g.controller) & (table.generation == g.generation)].iloc[0]
        assert (row.best, row["mean"]) == (g.best, g.mean)
        assert g.condition == ""


def test_ctrl_c_stops_at_a_generation_and_resume_finishes_the_same_run(tmp_path):
    whole = py_run(tmp_path / "whole", generations=3)
    calls = []

    def interrupt(g):
        calls.append(g)
        if len(calls) == 2:   # a real SIGINT, as Ctrl-C sends it
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        py_run(tmp_path / "stopped", generations=3, progress=interrupt)
    assert (tmp_path / "stopped" / "esc.db").exists()
    resumed = esc.resume(tmp_path / "stopped")
    same_table(resumed.table(), whole.table())
    again = esc.resume(tmp_path / "stopped")   # complete: nothing to do
    same_table(again.table(), whole.table())


def test_resume_carries_on_and_runs_studies(tmp_path):
    script = tmp_path / "tiny_study.esc"
    script.write_text(STUDY_TEXT)
    seen = []
    study = esc.run(script, generations=1, set=STUDY_SETTINGS, out=tmp_path / "study", threads=2, progress=seen.append)
    assert study.study == "tiny"
    assert {g.condition for g in seen} == {"inertia_on", "inertia_off"}
    longer = esc.resume(tmp_path / "study", generations=2)
    assert longer.table().generation.max() == 1


def test_refusals(tmp_path):
    with pytest.raises(esc.ScriptError) as script_error:
        bad = tmp_path / "bad.esc"
        bad.write_text("experiment e {\n  epochs 2 x 10 stepz\n}\n")
        esc.run(bad, out=tmp_path / "never")
    assert script_error.value.line == 2
    with pytest.raises(esc.Error) as setting:
        py_run(tmp_path / "never", set={**HOMING["settings"], "epochs": 0})
    assert setting.value.kind == "setting" and "epochs=0" in str(setting.value)
    with pytest.raises(esc.Error) as missing:
        esc.resume(tmp_path / "nowhere")
    assert missing.value.kind == "results"
    with pytest.raises(ValueError):
        esc.run(esc.compile(STUDY_TEXT))   # text: no file to store and resume from
    assert not (tmp_path / "never").exists()
