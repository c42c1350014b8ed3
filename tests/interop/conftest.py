# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Fixtures: a private network per test (config dirs + a free name-server port), a process group
stopped at teardown, the two tool sets, and name servers of either implementation."""
from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))

from interop_net import free_port_block  # noqa: E402
from interop_peer import ROOT, PrivateNetwork  # noqa: E402
from interop_procs import ProcessGroup  # noqa: E402
from interop_tools import RobogeneTools, YarpTools  # noqa: E402


@pytest.fixture
def procs(request):
    group = ProcessGroup()
    yield group
    if getattr(request.node, "rep_call", None) is not None and request.node.rep_call.failed:
        print("\n--- processes of the failed test ---\n" + group.describe())
    group.stop_all()


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    rep = outcome.get_result()
    setattr(item, f"rep_{rep.when}", rep)


@pytest.fixture
def net(tmp_path):
    return PrivateNetwork.create(tmp_path / "net", free_port_block())


@pytest.fixture
def other_net(tmp_path):
    """A second, independent network: for running the same script against a reference set-up."""
    return PrivateNetwork.create(tmp_path / "other-net", free_port_block())


@pytest.fixture
def yarp(procs, net):
    return YarpTools(procs, net)


@pytest.fixture
def ours(procs, net):
    return RobogeneTools(procs, net)


@pytest.fixture
def yarpserver(yarp):
    return yarp.server()


@pytest.fixture(scope="session")
def yarp_bottle_vectors():
    path = ROOT / "tests" / "vectors" / "yarp3_bottles.json"
    return json.loads(path.read_text())
