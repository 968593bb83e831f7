"""`ballscrew.__version__` is the crate's version: the one in Cargo.toml, the wheel's, the command line's."""

import importlib.metadata
import re
import sys

import pytest

import ballscrew

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    tomllib = pytest.importorskip("tomli")


def cargo_version(root):
    """The Python crate's version as Cargo.toml gives it (its own, or the workspace's)."""
    version = tomllib.loads((root / "crates" / "py" / "Cargo.toml").read_text())["package"]["version"]
    if version == {"workspace": True}:
        version = tomllib.loads((root / "Cargo.toml").read_text())["workspace"]["package"]["version"]
    return version


def test_version_is_the_crates(repo_root):
    assert isinstance(ballscrew.__version__, str)
    assert re.fullmatch(r"\d+\.\d+\.\d+(\S*)", ballscrew.__version__)
    assert ballscrew.__version__ == cargo_version(repo_root)
    assert ballscrew.__version__ == ballscrew._ballscrew.__version__


def test_version_is_the_installed_wheels():
    # maturin gives the wheel the crate's version (a pre-release in PEP 440 spelling, 0.2.0a1 for 0.2.0-alpha.1).
    installed = importlib.metadata.version("ballscrew")
    if "-" not in ballscrew.__version__:
        assert installed == ballscrew.__version__
    else:
        assert installed.startswith(ballscrew.__version__.split("-")[0])


def test_version_is_the_command_lines(cli):
    assert cli("--version").split() == ["ballscrew", ballscrew.__version__]
