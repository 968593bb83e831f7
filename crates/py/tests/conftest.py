"""Shared fixtures: the repository root, the command-line binary for parity tests, a watch on
the main thread while a call runs in another."""

import json
import os
import shutil
import subprocess
import threading
import time
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

    run.path = path  # the binary, for a test that reads its stderr
    return run


@pytest.fixture
def assert_releases_the_gil():
    """Runs call() in a worker thread while the main thread ticks about once a millisecond, and
    asserts that it kept ticking (skips when the call is too short to watch)."""

    def check(call) -> None:
        ticks = []
        done = threading.Event()

        def run():
            call()
            done.set()

        worker = threading.Thread(target=run)
        start = time.perf_counter()
        worker.start()
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)
        worker.join()
        elapsed = time.perf_counter() - start
        if elapsed < 0.05:
            pytest.skip(f"the call took {elapsed:.3f} s: too short to watch the main thread")
        # With the GIL held the main thread would tick once or twice; free, about once a millisecond.
        assert len(ticks) >= 0.2 * elapsed / 0.001

    return check
