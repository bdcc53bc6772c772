"""Shared fixtures of the chaplygin_lab tests: the module, the source tree, and the command line
of the same build (CHAPLYGIN_CLI) with its CSV parsed into columns of floats."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("CHAPLYGIN_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))


def cli_path():
    path = os.environ.get("CHAPLYGIN_CLI")
    if not path:
        pytest.skip("the comparisons with the command line need the program (CHAPLYGIN_BUILD_UI)")
    return path


def run_cli(*args):
    """The headless program's standard output for ARGS."""
    done = subprocess.run([cli_path(), "--headless", *args], capture_output=True, text=True,
                          env={**os.environ, "QT_QPA_PLATFORM": "offscreen"})
    assert done.returncode == 0, done.stderr
    return done.stdout


def parse_csv(text):
    """The CSV's header and its columns as the text of each field, by name."""
    lines = text.strip().split("\n")
    header = lines[0].split(",")
    fields = [line.split(",") for line in lines[1:]]
    assert all(len(f) == len(header) for f in fields)
    return header, {name: [f[i] for f in fields] for i, name in enumerate(header)}


def cli_csv(*args):
    """run_cli(*args, "--csv", "-") parsed: (header, {name: [field text]})."""
    return parse_csv(run_cli(*args, "--csv", "-"))


def floats(texts):
    return np.array([float(t) for t in texts])


@pytest.fixture(scope="session")
def cl():
    import chaplygin_lab
    return chaplygin_lab
