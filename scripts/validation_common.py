"""What scripts/validate-cmaes.py and validate-nsga2.py share: their command line and the
machine line of the tables they print."""
import argparse
import os
import platform


def arguments(doc):
    """--esc (esc-testfn), --seeds, --jobs, --out, parsed."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--esc", default=os.path.join(here, "..", "build", "tools", "testfn", "esc-testfn"))
    parser.add_argument("--seeds", type=int, default=15)
    parser.add_argument("--jobs", type=int, default=os.cpu_count())
    parser.add_argument("--out")
    return parser.parse_args()


def machine():
    """The CPU model and the number of logical CPUs, for a table's caption."""
    try:
        with open("/proc/cpuinfo") as f:
            models = [line.split(":", 1)[1].strip() for line in f if line.startswith("model name")]
    except OSError:
        models = []
    return f"{models[0] if models else platform.processor()}, {len(models) or os.cpu_count()} logical CPUs"
