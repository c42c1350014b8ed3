# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The mcast, shmem and http carriers end to end through the CLI and a real `robogene server`:
`robogene connect /w /r mcast|shmem` between `robogene write` and `robogene read` processes, a
web client (http.client, urllib, curl when installed) talking to a port, and peers that send
garbage, stop half way or vanish: the port closes that connection with a log line and goes on."""
from __future__ import annotations

import http.client
import json
import re
import shutil
import signal
import socket
import subprocess
import time
import urllib.error
import urllib.request

import pytest

pytestmark = pytest.mark.timeout(90)


def ok(result):
    assert result.returncode == 0, f"exit {result.returncode}\nstdout: {result.stdout}\nstderr: {result.stderr}"
    return result.stdout


def start_read(procs, robogene_bin, yarp_env, name):
    proc = procs.start(f"read {name}", [robogene_bin, "read", name], yarp_env)
    proc.wait_for_line(rf"Port {name} active at tcp://", stream="err")
    return proc


def start_write(procs, robogene_bin, yarp_env, name):
    proc = procs.start(f"write {name}", [robogene_bin, "write", name], yarp_env)
    proc.wait_for_line(rf"Port {name} active", stream="err")
    return proc


def address(cli, name):
    m = re.search(r"ip ([\d.]+) port (\d+)", ok(cli("name", "query", name)))
    return m.group(1), int(m.group(2))


def wait_until(predicate, timeout=10.0, what="condition"):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return
        time.sleep(0.05)
    raise AssertionError(f"timed out waiting for {what}")


def mcast_groups(cli):
    """The groups allocated to connections (the server's own `fallback` group is not one)."""
    return [l for l in ok(cli("name", "list")).splitlines()
            if l.endswith("type mcast") and not l.startswith("registration name fallback ")]


def test_mcast_one_stream_reaches_every_reader_once(name_server, procs, robogene_bin, yarp_env, cli):
    readers = {n: start_read(procs, robogene_bin, yarp_env, n) for n in ("/r1", "/r2", "/r3")}
    writer = start_write(procs, robogene_bin, yarp_env, "/w")
    for n in readers:
        assert ok(cli("connect", "/w", n, "mcast")) == f"Success: Added connection from /w to mcast:/{n}\n"
    groups = mcast_groups(cli)
    assert len(groups) == 1 and re.search(r"ip 224\.1\.\d+\.\d+ port \d+", groups[0]), groups
    owner = ok(cli("rpc", "/root", input="bot get /w owns\n"))
    assert groups[0].split()[2] in owner, owner
    ls = ok(cli("ls"))
    assert all(f"  -> {n} (mcast)" in ls for n in readers), ls
    for i in range(5):
        writer.send(f"{i} tick\n")
    for proc in readers.values():
        proc.wait_for_line("^4 tick$")
    time.sleep(0.3)  # a duplicate would arrive within this
    for proc in readers.values():
        assert proc.out == [f"{i} tick" for i in range(5)], proc.describe()
    # Disconnecting one reader ends its input out of band; the others keep the stream.
    assert ok(cli("disconnect", "/w", "/r2")) == "Success: Removed connection from /w to /r2\n"
    wait_until(lambda: "<- /w" not in ok(cli("ls")).split("/r2  ")[1].split("\n/")[0], what="/r2 input gone")
    writer.send("after\n")
    readers["/r1"].wait_for_line("^after$")
    readers["/r3"].wait_for_line("^after$")
    time.sleep(0.3)
    assert "after" not in readers["/r2"].out
    # The writer leaving ends the inputs and gives the group back.
    writer.close_stdin()
    assert writer.wait_exit() == 0
    wait_until(lambda: "<- /w" not in ok(cli("ls")), what="inputs from /w gone")
    assert mcast_groups(cli) == []


def test_mcast_bad_group_is_refused_with_a_log_line(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/r")
    host, port = address(cli, "/r")
    with socket.create_connection((host, port), timeout=5) as s:
        # mcast header, sender /x, then 10.0.0.1:10769, which is not a multicast group
        s.sendall(bytes.fromhex("5941621e00005250") + b"\x03\x00\x00\x00/x\x00" + bytes([10, 0, 0, 1, 0x2a, 0x11]))
        s.settimeout(5)
        assert s.recv(100) == b""  # closed
    reader.wait_for_line(r"rejected a connection.*10\.0\.0\.1:10769 is not a multicast group", stream="err")
    writer = start_write(procs, robogene_bin, yarp_env, "/w")
    ok(cli("connect", "/w", "/r"))
    writer.send("still serving\n")
    reader.wait_for_line("^still serving$")


def test_shmem_between_processes(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/r")
    writer = start_write(procs, robogene_bin, yarp_env, "/w")
    assert ok(cli("connect", "/w", "/r", "shmem")) == "Success: Added connection from /w to shmem://r\n"
    assert "  -> /r (shmem)" in ok(cli("ls"))
    big = " ".join(str(i) for i in range(20000))  # ~110 kB in one bottle
    writer.send("1 2.5 \"hi\" [set]\n" + big + "\n")
    reader.wait_for_line(r"^1 2\.5 hi \[set\]$")
    reader.wait_for_line("^0 1 2 .* 19999$")
    assert not [p for p in __import__("os").listdir("/dev/shm") if p.startswith("robogene-shmem-")], \
        "the segment's name must be unlinked once both sides mapped it"
    writer.close_stdin()
    assert writer.wait_exit() == 0
    wait_until(lambda: "<- /w" not in ok(cli("ls")), what="shmem input gone after the writer's q")


def test_shmem_writer_killed_is_noticed_and_the_reader_goes_on(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/r")
    writer = start_write(procs, robogene_bin, yarp_env, "/w")
    ok(cli("connect", "/w", "/r", "shmem"))
    writer.send("before\n")
    reader.wait_for_line("^before$")
    writer.signal(signal.SIGKILL)
    writer.wait_exit()
    wait_until(lambda: "<- /w" not in ok(cli("ls")).split("/r  ")[1].split("\n/")[0], what="input of the killed writer gone")
    again = start_write(procs, robogene_bin, yarp_env, "/w2")
    ok(cli("connect", "/w2", "/r", "shmem"))
    again.send("after\n")
    reader.wait_for_line("^after$")
    assert reader.popen.poll() is None


def test_http_writes_are_refused_by_default(name_server, procs, robogene_bin, yarp_env, cli):
    # A web page can make the browser send any GET or form POST to the robot: refused with 403
    # and nothing reaches the reader, unless ROBOGENE_HTTP_WRITES=1 (docs/security.md).
    reader = start_read(procs, robogene_bin, yarp_env, "/r")
    host, port = address(cli, "/r")
    with pytest.raises(urllib.error.HTTPError) as refused:
        urllib.request.urlopen(f"http://{host}:{port}/data=%5Bset%5D+%5Bpos%5D+1+30", timeout=5)
    assert refused.value.code == 403 and "Access-Control-Allow-Origin" not in refused.value.headers
    assert "HTTP writes to this port are off" in refused.value.read().decode()
    form = urllib.parse.urlencode({"data": "[set] [pos] 1 30.5"}).encode()
    with pytest.raises(urllib.error.HTTPError) as refused:
        urllib.request.urlopen(urllib.request.Request(f"http://{host}:{port}/form", data=form), timeout=5)
    assert refused.value.code == 403
    # The name server answers browsers' reads but not their writes.
    with pytest.raises(urllib.error.HTTPError) as refused:
        urllib.request.urlopen(f"http://{name_server.address}/data=unregister+%2Fr", timeout=5)
    assert refused.value.code == 403
    # A legitimate local writer still gets through, and /r is still registered.
    writer = start_write(procs, robogene_bin, yarp_env, "/w")
    ok(cli("connect", "/w", "/r"))
    writer.send("after\n")
    reader.wait_for_line("^after$")
    assert not any("set" in line for line in reader.out)
    assert "/r" in ok(cli("ls"))


def test_http_browser_view_of_a_port(name_server, procs, robogene_bin, yarp_env, cli):
    yarp_env["ROBOGENE_HTTP_WRITES"] = "1"  # this test is about what HTTP writes do
    reader = start_read(procs, robogene_bin, yarp_env, "/r")
    host, port = address(cli, "/r")
    conn = http.client.HTTPConnection(host, port, timeout=5)
    conn.request("GET", "/")
    resp = conn.getresponse()
    page = resp.read().decode()
    assert resp.status == 200 and resp.getheader("Content-Type").startswith("text/html")
    assert "<h1>yarp port /r</h1>" in page and f"This is /r at tcp://{host}:{port}/" in page
    # Data typed into the URL (as the page's links do) and posted from the page's form.
    with urllib.request.urlopen(f"http://{host}:{port}/data=hello+%22big+world%22", timeout=5) as r:
        assert r.status == 200
    reader.wait_for_line(r'^hello "big world"$')
    form = urllib.parse.urlencode({"data": "[set] [pos] 1 30.5"}).encode()
    with urllib.request.urlopen(urllib.request.Request(f"http://{host}:{port}/form", data=form), timeout=5) as r:
        assert r.status == 200
    reader.wait_for_line(r"^\[set\] \[pos\] 1 30\.5$")
    # The name server is a port too: its page lists the registrations (YARP's "All ports").
    with urllib.request.urlopen(f"http://{name_server.address}/data=list", timeout=5) as r:
        listing = r.read().decode()
    assert "registration name /r ip" in listing


def test_http_calls_and_json_from_an_rpc_port(name_server, procs, robogene_bin, yarp_env, cli):
    # `robogene server`'s /root answers calls: "bot query /root" from a URL, as text and as JSON.
    # (As in YARP, the request also carries the fields and the target: `... (REQUEST_URI "...")`.)
    with urllib.request.urlopen(f"http://{name_server.address}/bot/query/%2Froot", timeout=5) as r:
        text = r.read().decode()
    assert text.startswith('port (name "/root")'), text
    with urllib.request.urlopen(f"http://{name_server.address}/bot/query/%2Froot?format=json", timeout=5) as r:
        assert r.getheader("Content-Type") == "application/json"
        reply = json.load(r)
    assert reply[:2] == ["port", ["name", "/root"]] and ["port_number", int(name_server.port)] in reply, reply


@pytest.mark.skipif(shutil.which("curl") is None, reason="curl is not installed")
def test_http_read_stream_with_curl(name_server, procs, robogene_bin, yarp_env, cli):
    # At info level, so the port's note that the browser hung up is printed.
    writer = start_write(procs, robogene_bin, dict(yarp_env, ROBOGENE_LOG="info"), "/w")
    host, port = address(cli, "/w")
    curl = procs.start("curl /r", ["curl", "-sN", f"http://{host}:{port}/r"], yarp_env)
    curl.wait_for_line("Reading data from port")
    time.sleep(0.3)  # the port adds the browser as an output just after sending that first chunk
    writer.send('1 "<b>"\n')
    curl.wait_for_line(r"^1 &quot;&lt;b&gt;&quot;$")
    curl.stop()
    # The browser's leaving drops its output: seen by the port watching the socket for the hang-up,
    # or by the next write failing, whichever comes first.
    dropped = r"Removing output from /w to web \(the reader hung up\)|dropping output to web"
    deadline = time.monotonic() + 10
    while not any(re.search(dropped, l) for l in writer.err) and time.monotonic() < deadline:
        writer.send("tick\n")
        time.sleep(0.1)
    writer.wait_for_line(dropped, stream="err")


def test_http_garbage_and_truncation_are_closed_with_a_log_line(name_server, procs, robogene_bin, yarp_env, cli):
    reader = start_read(procs, robogene_bin, yarp_env, "/r")
    host, port = address(cli, "/r")
    for request in (b"GET /" + b"x" * 20000 + b" HTTP/1.1\r\n\r\n",        # line too long
                    b"POST /form HTTP/1.1\r\nContent-Length: 5\r\n\r\nda"):  # body cut short
        with socket.create_connection((host, port), timeout=5) as s:
            try:
                s.sendall(request)
                s.shutdown(socket.SHUT_WR)
                s.settimeout(5)
                assert s.recv(100) == b"", "a bad request must get no answer"
            except (ConnectionResetError, BrokenPipeError):
                pass  # closed with our unread bytes still queued: a reset is a close too
            except OSError as e:
                assert e.errno == 107, e  # closed before we finished sending: also a close
    reader.wait_for_line(r"rejected a connection.*longer than 8192 bytes", stream="err")
    reader.wait_for_line(r"rejected a connection", stream="err")
    with urllib.request.urlopen(f"http://{host}:{port}/", timeout=5) as r:
        assert r.status == 200
