"""Shared fixtures: the repository root, the command-line binary for parity tests."""

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def repo_root() -> Path:
    return ROOT


def _build_cli() -> Path:
    """Builds the `ballscrew` binary with cargo (release) and returns its path."""
    if shutil.which("cargo") is None:
        pytest.skip("cargo not found: set BALLSCREW_CLI to the ballscrew binary for the parity tests")
    out = subprocess.run(
        ["cargo", "build", "--release", "-p", "ballscrew-cli", "--message-format=json"],
        cwd=ROOT,
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    for line in out.splitlines():
        msg = json.loads(line)
        if msg.get("reason") == "compiler-artifact" and msg.get("executable") and msg["target"]["name"] == "ballscrew":
            return Path(msg["executable"])
    raise RuntimeError("cargo built no ballscrew binary")


@pytest.fixture(scope="session")
def cli():
    """Runs the command line: cli("sweep", "--format", "json") -> stdout text."""
    path = Path(os.environ["BALLSCREW_CLI"]) if os.environ.get("BALLSCREW_CLI") else _build_cli()
    assert path.is_file(), f"no ballscrew binary at {path}"

    def run(*args: str) -> str:
        return subprocess.run([str(path), *args], check=True, capture_output=True, text=True).stdout

    return run
