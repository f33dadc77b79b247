"""Fixtures of the Python module's tests (ctest label `python`): the repository, the voxgi
command beside the module (VOXGI_BIN) and small scenes (16^3 grids, 64-pixel images)."""
import os
import pathlib

import pytest

import voxgi

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture(scope="session")
def voxgi_bin():
    path = os.environ.get("VOXGI_BIN")
    if not path:
        pytest.fail("VOXGI_BIN names the voxgi command (ctest sets it)")
    return path


@pytest.fixture(scope="session")
def box():
    return voxgi.load_scene(REPO / "scenes" / "cornell_box.json", resolution=16, image=64)
