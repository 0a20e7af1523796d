"""esc.compile: a script from a file or from text, its settings, and its errors as the esc
program reports them."""

import os
from pathlib import Path

import pytest

import esc
from conftest import EXPERIMENTS, HOMING, STUDY_TEXT, run_esc

TYPO = 'import "lib/khepera.esc"\n\ncontroller c = mlp(ir[0..7] -> hiden 3 -> wheels)\n'


def test_a_file_gives_its_experiments_controllers_and_settings():
    script = esc.compile(HOMING["script"])
    assert script.experiments == ["homing"]
    assert script.studies == {}
    controllers = script.controllers["homing"]
    assert list(controllers) == ["CC", "SC", "SV"]
    sc = controllers["SC"]
    assert (sc.architecture, sc.head, sc.genome_size) == ("17-5r-6", "symbolic", 5 * (1 + 17 + 5) + 6 * (1 + 5))
    assert sc.inputs == tuple(f"ir[{i}]" for i in range(8)) + tuple(f"light[{i}]" for i in range(8)) + ("energy",)
    assert sc.choices == ("forward", "left", "right")
    assert controllers["SV"].head == "supervisor"
    assert script.settings["homing"]["epochs"] == "5"


def test_settings_are_applied_as_esc_run_set_applies_them():
    script = esc.compile(Path(HOMING["script"]), {"epochs": 2, "robot.time_constant": "50ms", "robot.inertia": False})
    settings = script.settings["homing"]
    assert settings["epochs"] == "2"
    assert settings["robot.inertia"] == "off"


def test_a_setting_refused_is_an_error_with_the_clis_message():
    with pytest.raises(esc.Error, match=r"epoch=3: unknown setting `epoch`; did you mean `epochs`\?"):
        esc.compile(HOMING["script"], {"epoch": 3})
    with pytest.raises(esc.Error, match="mu=0"):
        esc.compile(HOMING["script"], {"mu": 0})


def test_settings_some_experiments_refuse_leave_the_others_usable():
    # beacons.esc: `robots` suits its one-body experiment, not its group of two bodies (whose
    # counts are each body's), as `esc run --experiment E --set robots=3` fails for that E alone.
    script = esc.compile(EXPERIMENTS / "examples" / "beacons.esc", {"robots": 3})
    assert sorted(script.refused) == ["beacons_or_dark", "leader_aggregation"]
    assert "experiment `leader_aggregation`: robots=3:" in script.refused["leader_aggregation"]
    assert "several bodies" in script.refused["leader_aggregation"]
    assert script.settings["beacon_aggregation"]["robots"] == "3"
    assert list(script.settings) == list(script.controllers) == ["beacon_aggregation"]
    env = esc.ParallelEnv(script, "beacon_aggregation")
    assert len(env.possible_agents) == 3
    with pytest.raises(esc.Error, match="experiment `leader_aggregation`: robots=3: .*several bodies"):
        esc.ParallelEnv(script, "leader_aggregation")
    with pytest.raises(esc.Error, match="several bodies"):
        script.controller("leader_aggregation", "cc")
    assert esc.compile(EXPERIMENTS / "examples" / "beacons.esc", {"epochs": 2}).refused == {}
    # Refused by every experiment and by every study (one condition is enough): an error.
    two = 'import "lib/khepera.esc"\narena a { size 1m x 1m }\nfitness f { step: forward_speed }\n' \
          'controller c = mlp(ir[0..7] -> wheels)\n' \
          'experiment e { arena a  fitness f  compare c  robot khepera x 2 }\n' \
          'study s { condition a = e  condition b = e { robots 4 } }\n'
    with pytest.raises(esc.Error, match="roles=3"):
        esc.compile(two, {"roles": 3})


def test_one_bodys_setting_sets_that_body_alone():
    # beacons.esc: `leader_aggregation` is a lit robot and four dark ones, two bodies;
    # `beacon_aggregation` has one body, and refuses a second's setting.
    script = esc.compile(EXPERIMENTS / "examples" / "beacons.esc", {"body2.emission": 0.5})
    assert script.settings["leader_aggregation"]["body2.emission"] == "0.5"
    assert script.settings["leader_aggregation"]["robot.emission"] == "1"
    assert "the robots of experiment `beacon_aggregation` have one body" in script.refused["beacon_aggregation"]
    with pytest.raises(esc.Error, match="`robot.emission` sets every body of the group and `body2.emission` one"):
        esc.compile(EXPERIMENTS / "examples" / "beacons.esc", {"robot.emission": 1, "body2.emission": 0.5})


def test_bodies_name_each_experiments_robots_and_their_sensors():
    mixed = esc.compile(EXPERIMENTS / "examples" / "two_bodies.esc").bodies["mixed_dispersion"]
    assert [(b.name, b.robots, b.drive) for b in mixed] == [("khepera", 3, "differential"), ("epuck_ir", 3, "differential")]
    assert (mixed[0].radius_m, mixed[1].radius_m) == (0.0275, 0.037)
    assert mixed[0].outline_m == mixed[1].outline_m == ()
    assert mixed[1].sensors == tuple(f"ir[{i}]" for i in range(8)) + tuple(f"light[{i}]" for i in range(8)) + ("energy",)
    [thymio] = esc.compile(EXPERIMENTS / "bodies" / "thymio_obstacle_avoidance.esc").bodies["thymio_obstacle_avoidance"]
    assert (thymio.name, thymio.robots, thymio.radius_m) == ("thymio2", 1, 0.08)
    assert len(thymio.outline_m) > 3 and all(len(corner) == 2 for corner in thymio.outline_m)
    assert thymio.sensors[0] == "prox_horizontal[0]" and "prox_ground[1]" in thymio.sensors


def test_text_compiles_with_the_standard_library_and_a_study():
    script = esc.compile(STUDY_TEXT)
    assert script.file == "<script>"
    assert script.studies == {"tiny": ["inertia_on", "inertia_off"]}
    assert script.experiments == []


def test_text_imports_relative_to_the_working_directory(tmp_path, monkeypatch):
    (tmp_path / "mine.esc").write_text('behavior spin() { wheels(-0.5, 0.5) }\n')
    monkeypatch.chdir(tmp_path)
    script = esc.compile('import "mine.esc"\nimport "examples/quick_start.esc"\n')
    assert script.studies == {}
    with pytest.raises(esc.ScriptError, match="cannot find `absent.esc`"):
        esc.compile('import "absent.esc"\n')


def test_a_typo_raises_script_error_at_the_line_the_cli_prints(tmp_path):
    bad = tmp_path / "typo.esc"
    bad.write_text(TYPO)
    cli = run_esc("check", bad, check=False)
    assert cli.returncode == 1
    with pytest.raises(esc.ScriptError) as caught:
        esc.compile(str(bad))
    e = caught.value
    assert isinstance(e, esc.Error) and isinstance(e, Exception)
    assert (e.file, e.line, e.column) == (str(bad), 3, 32)
    assert e.message == "unknown layer `hiden`; did you mean `hidden`?"
    assert cli.stderr.splitlines()[0] == f"{e.file}:{e.line}:{e.column}: error: {e.message}"
    assert str(e) == cli.stderr.rstrip("\n")
    assert [d.severity for d in e.diagnostics] == ["error"]
    assert e.diagnostics[0].length == len("hiden")


def test_a_typo_in_text_is_located_in_the_pseudo_file():
    with pytest.raises(esc.ScriptError) as caught:
        esc.compile(TYPO)
    assert (caught.value.file, caught.value.line, caught.value.column) == ("<script>", 3, 32)
    assert str(caught.value).startswith("<script>:3:32: error: unknown layer `hiden`")


def test_every_error_is_reported():
    text = TYPO + "controller d = mlp(ir[0..9] -> wheels)\n"
    with pytest.raises(esc.ScriptError) as caught:
        esc.compile(text)
    errors = [d for d in caught.value.diagnostics if d.severity == "error"]
    assert len(errors) == 2
    assert errors[1].line == 4
    assert caught.value.line == 3


def test_a_missing_file_is_file_not_found(tmp_path):
    with pytest.raises(FileNotFoundError):
        esc.compile(tmp_path / "absent.esc")
    with pytest.raises(FileNotFoundError):
        esc.compile(os.path.join(str(tmp_path), "absent.esc"))


def test_shipped_scripts_compile():
    for script in (EXPERIMENTS / "paper" / "obstacle_avoidance.esc", EXPERIMENTS / "gp" / "nn_vs_gp.esc"):
        assert esc.compile(script).experiments
