"""esc.open: a run directory's summary, tables equal to `esc export`'s, best genomes; errors;
and that reading changes nothing, in a read-only directory too."""

import hashlib
import io
import json
import os
import shutil
import stat
import subprocess
import time

import numpy as np
import pandas as pd
import pytest

import esc
from conftest import EXPERIMENTS, SOURCE, best_json, esc_program, run_esc


def export(directory, table: str) -> str:
    """`esc export DIR [--table NAME] --format csv`: generations are the export without --table."""
    named = [] if table == "generations" else ["--table", table]
    return run_esc("export", directory, *named, "--format", "csv").stdout


@pytest.mark.parametrize("table", ["generations", "usage", "metrics", "comparisons"])
def test_a_table_equals_esc_export(homing_run, table):
    run = esc.open(str(homing_run))
    frame = run.table(table)
    cli = export(homing_run, table)
    assert run._stored.table_csv(table) == cli
    exact = pd.read_csv(io.StringIO(cli), float_precision="round_trip")
    pd.testing.assert_frame_equal(frame, exact, check_exact=True)
    pd.testing.assert_frame_equal(frame, pd.read_csv(io.StringIO(cli)))   # dtypes as pandas reads the CLI's
    if table == "generations":
        assert len(frame) == 3 * 2   # 3 controllers x 1 run x 2 generations
        assert run.table().equals(frame)


def test_an_archive_is_a_table_any_generation_of_it_is_read_back_from(tmp_path):
    directory = tmp_path / "map"
    run_esc("run", EXPERIMENTS / "examples" / "behavior_map.esc", "--runs", 1, "--generations", 4, "--set", "epochs=1",
            "--out", directory)
    run = esc.open(directory)
    archive = run.table("archive")
    assert run._stored.table_csv("archive") == export(directory, "archive")
    assert list(archive.columns[-3:]) == ["forward_avoid", "turning", "explored"]
    coverage = run.table("metrics").query("metric == 'coverage'").set_index("generation")["value"]
    for g in range(4):
        cells = archive[archive.generation <= g].groupby(["run", "cell"]).last()
        assert len(cells) == round(coverage[g] * 100), g   # 10 x 10 cells
    assert run.table("front").empty


@pytest.mark.parametrize("example", ["behavior_map", "speed_energy"])
def test_members_are_measured_again_in_their_own_evaluations(tmp_path, example):
    """A final archive's elites (MAP-Elites) and a final front's members (NSGA-II), random
    starts both: their genomes, measured again with the seeds of the evaluations that measured
    them, give back every stored objective and descriptor bit for bit."""
    script = EXPERIMENTS / "examples" / f"{example}.esc"
    directory = tmp_path / example
    run_esc("run", script, "--runs", 1, "--generations", 3, "--set", "epochs=1", "--out", directory)
    run = esc.open(directory)
    controller = run.controllers[0]
    members = run.members(controller, 1)
    assert members and {m.kind for m in members} == {"archive" if example == "behavior_map" else "front"}
    assert all(m.evaluation_seed is not None and 0 <= m.generation < 3 for m in members)
    measured = esc.measure(esc.compile(script, {"epochs": 1}), run.experiments[0], controller,
                           np.array([m.genome for m in members]), seed=[m.evaluation_seed for m in members])
    for m, (_, row) in zip(members, measured.iterrows()):
        assert m.objectives and all(row[name] == value for name, value in m.objectives.items()), m.cell
        assert m.descriptors.tolist() == row.iloc[len(row) - len(m.descriptors):].tolist(), m.cell


def test_an_optimizer_without_members_is_an_error(homing_run):
    with pytest.raises(esc.Error, match="keeps no front or archive"):
        esc.open(homing_run).members("SC", 1)


def test_a_studys_table_conditions_and_best(study_run):
    run = esc.open(study_run)
    assert run.study == "tiny"
    assert run.conditions == ["inertia_on", "inertia_off"]
    assert run.controllers == ["cc", "sc"]
    frame = run.table()
    pd.testing.assert_frame_equal(frame, pd.read_csv(io.StringIO(export(study_run, "generations")),
                                                     float_precision="round_trip"), check_exact=True)
    assert set(frame["condition"]) == {"inertia_on", "inertia_off"}
    # The end table's pairs: cc against sc in each condition, each controller across the two.
    pairs = run.table("comparisons")
    assert len(pairs) == 4 and set(pairs["study"]) == {"tiny"}
    stored = best_json(study_run / "inertia_off", "sc")
    assert run.best("sc", 1, condition="inertia_off").fitness == stored["fitness"]
    with pytest.raises(ValueError, match="name a condition"):
        run.best("sc", 1)
    with pytest.raises(ValueError, match="did you mean `inertia_on`"):
        run.best("sc", 1, condition="inertia_onn")


def test_summary_controllers_and_best_genomes(homing_run):
    run = esc.open(homing_run)
    assert run.study is None and run.conditions == [] and run.experiments == ["homing"]
    assert run.controllers == ["CC", "SC", "SV"]
    assert run.summary == json.loads((homing_run / "summary.json").read_text())
    for controller in run.controllers:
        stored = best_json(homing_run, controller)
        genome = run.best_genome(controller, 1)
        assert genome.dtype == np.float64
        assert genome.tolist() == stored["genome"]
        best = run.best(controller, 1)
        assert (best.fitness, best.generation, best.individual) == (stored["fitness"], stored["generation"],
                                                                    stored["individual"])
        assert best.evaluation_seed == int(stored["evaluation_seed"])
        assert best.run_seed == int(stored["seed"])
        assert esc.evaluation_seed(best.run_seed, best.generation, best.individual) == best.evaluation_seed


def test_a_tree_is_its_text_or_encoded(tree_run):
    run = esc.open(tree_run)
    for controller in ("GW", "GS"):
        stored = best_json(tree_run, controller)
        assert run.best_genome(controller, 1) == stored["tree"]
        encoded = run.best_genome(controller, 1, encoded=True)
        assert encoded.dtype == np.float64 and encoded.tolist() == stored["genome"]


def test_unknown_names_are_value_errors(homing_run):
    run = esc.open(homing_run)
    with pytest.raises(ValueError, match="did you mean `usage`"):
        run.table("usages")
    with pytest.raises(ValueError, match=r"run=2: expected an integer in 1\.\.1"):
        run.best_genome("CC", 2)
    with pytest.raises(ValueError, match="did you mean `SC`"):
        run.best_genome("SCX", 1)


def test_a_missing_directory_is_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError):
        esc.open(tmp_path / "absent")


def test_a_directory_that_is_no_run_is_an_error_with_the_stores_message(tmp_path):
    cli = run_esc("export", tmp_path, check=False)
    assert cli.returncode == 1
    with pytest.raises(esc.Error) as caught:
        esc.open(tmp_path)
    assert not isinstance(caught.value, esc.ScriptError)
    assert f"esc: error: {caught.value}" in cli.stderr
    (tmp_path / "esc.db").write_text("not a database")
    with pytest.raises(esc.Error, match="not an esc database|damaged"):
        esc.open(tmp_path)


def snapshot(directory):
    """Every file's path, mode, size, modification time and content hash."""
    files = {}
    for root, dirs, names in os.walk(directory):
        for name in dirs + names:
            path = os.path.join(root, name)
            st = os.lstat(path)
            digest = hashlib.sha256(open(path, "rb").read()).hexdigest() if stat.S_ISREG(st.st_mode) else ""
            files[os.path.relpath(path, directory)] = (st.st_mode, st.st_size, st.st_mtime_ns, digest)
    return files


def test_a_read_only_directory_opens_and_nothing_changes(homing_run, tmp_path):
    copy = tmp_path / "read-only"
    shutil.copytree(homing_run, copy)
    for root, dirs, names in os.walk(copy):
        for name in names:
            os.chmod(os.path.join(root, name), 0o444)
        os.chmod(root, 0o555)
    try:
        before = snapshot(copy)
        run = esc.open(copy)
        for table in ("generations", "usage", "metrics"):
            run.table(table)
        run.best_genome("SC", 1)
        assert run.summary["experiment"] == "homing"
        del run
        assert snapshot(copy) == before   # no -wal, -shm or journal appeared, no byte changed
    finally:
        for root, dirs, names in os.walk(copy):
            os.chmod(root, 0o755)


def test_a_damaged_log_is_said(tmp_path, caplog):
    """A bit flipped in a killed run's log (esc.db-wal): SQLite drops the commits from it on;
    esc.open says so to the "esc" logger, as `esc export` says it, and reads the rest."""
    directory = tmp_path / "killed"
    log = directory / "esc.db-wal"
    frame = 24 + 4096
    child = subprocess.Popen([esc_program(), "run", str(SOURCE / "tests/cli/data/tiny.esc"), "--generations", "200",
                              "--threads", "1", "--out", str(directory)],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 60
    while (not log.exists() or log.stat().st_size < 32 + 200 * frame) and time.monotonic() < deadline:
        time.sleep(0.02)
    child.kill()
    child.wait()
    damaged = bytearray(log.read_bytes())
    at = 32 + (len(damaged) - 32) // frame * 3 // 4 * frame + 24 + 1000   # a page late in the log
    damaged[at] ^= 0x08
    log.write_bytes(bytes(damaged))
    with caplog.at_level("WARNING", logger="esc"):
        run = esc.open(directory)
    assert "frames past its last valid commit (a damaged write-ahead log)" in caplog.text
    assert f"`esc run --resume {directory}` runs them again" in caplog.text
    assert len(run.table("generations")) > 0
