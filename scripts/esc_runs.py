"""What the analysis scripts of results/paper share: the finished runs of a run directory
(one experiment, or a study's conditions in their own directories) and replaying one run's
best controller with `esc replay`, and reading one of `esc export`'s tables."""
import csv
import io
import json
import os
import subprocess
import sys


def export(esc, directory, *extra):
    """`esc export DIRECTORY --format csv EXTRA...` as a list of rows (dicts by column)."""
    out = subprocess.run([esc, "export", directory, "--format", "csv", *extra], check=True,
                         capture_output=True, text=True).stdout
    return list(csv.DictReader(io.StringIO(out)))


def parts(directory):
    """(condition or experiment name, directory to replay from, its part of summary.json) for
    each experiment of DIR: a study's conditions sit in directories named in settings.json
    (a sweep point's name is not a file name), one experiment in DIR itself. summary.json
    lists finished runs only, so a campaign still running is read as far as it got."""
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    if "conditions" not in summary:
        return [(summary["experiment"], directory, summary)]
    with open(os.path.join(directory, "settings.json")) as f:
        where = {c["name"]: c["directory"] for c in json.load(f).get("conditions", [])}
    return [(c["name"], os.path.join(directory, where[c["name"]]), c) for c in summary["conditions"]]


def split_epochs(rows):
    """A replay's steps, epoch by epoch, in order."""
    epochs = {}
    for r in rows:
        epochs.setdefault(r["epoch"], []).append(r)
    return epochs.values()


def replay(esc, source, controller, run, scratch):
    """Every step of run `run` (from 1)'s best controller, as `esc replay` writes them."""
    out = os.path.join(scratch, f"{os.path.basename(os.path.normpath(source))}-{controller}-{run}")
    done = subprocess.run([esc, "replay", source, "--controller", controller, "--run", str(run), "--out", out],
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"esc replay {source} --controller {controller} --run {run} failed:\n{done.stderr}")
    with open(os.path.join(out, f"replay-{controller}-run-{run:02}.csv"), newline="") as f:
        return list(csv.DictReader(f))
