#!/usr/bin/env python3
"""Drives `drcc serve` with unmodified python-can (interface "socketcand"), as a
user's script would. Run by tests/serve.rs; exits 1 naming every failed check.

    serve_can.py basic HOST PORT    send/receive both ways, base and extended ids,
                                    1,000 frames round trip, a receive filter,
                                    reconnect, two clients at once
    serve_can.py cut HOST PORT      line A cut (the `< fault cut a 2 >` command)
                                    during traffic: every frame arrives exactly once
    serve_can.py beacon HOST PORT   python-can's beacon detection finds the buses

Frames carry a counter, so no two are alike: the DRCC's duplicate filter drops a
frame identical to one received less than its window (2,000 bit times) before.
"""

import socket
import sys
import time

import can

FAILED = []
PASSED = []


def check(name, cond, detail=""):
    (PASSED if cond else FAILED).append(name)
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else ": " + detail))


def bus(host, port, node, **kw):
    return can.Bus(interface="socketcand", host=host, port=port, channel=node, **kw)


def frames(b, n, timeout=60.0):
    """Up to n data frames (error frames skipped) within timeout seconds."""
    out, end = [], time.time() + timeout
    while len(out) < n:
        left = end - time.time()
        if left <= 0:
            break
        m = b.recv(timeout=left)
        if m is None:
            break
        if not m.is_error_frame:
            out.append(m)
    return out


def key(m):
    return (m.arbitration_id, m.is_extended_id, bytes(m.data))


def msg(ident, data, ext=False):
    return can.Message(arbitration_id=ident, is_extended_id=ext, data=data)


def basic(host, port):
    b0, b1 = bus(host, port, "node0"), bus(host, port, "node1")

    sent = [msg(0x123, [1, 2, 3]), msg(0x1ABCDE12, [0, 1, 2, 3, 4, 5, 6, 7], ext=True)]
    for m in sent:
        b0.send(m)
    got = frames(b1, 2)
    check("node0 -> node1, base and extended", list(map(key, got)) == list(map(key, sent)),
          f"got {got}")
    check("timestamps are simulated time, increasing",
          len(got) == 2 and 0 < got[0].timestamp < got[1].timestamp < 60, f"got {got}")
    back = [msg(0x321, [9]), msg(0x0ABCDEF, [], ext=True)]
    for m in back:
        b1.send(m)
    got = frames(b0, 2)
    check("node1 -> node0, base and extended", list(map(key, got)) == list(map(key, back)),
          f"got {got}")

    n = 1000
    out = [msg(0x200 + k % 0x100, k.to_bytes(2, "big") + bytes([0xA5, k % 256])) for k in range(n)]
    for m in out:
        b0.send(m)
    got = frames(b1, n)
    check("1,000 frames node0 -> node1, none lost, in order",
          list(map(key, got)) == list(map(key, out)), f"{len(got)} of {n} arrived")
    ret = [msg(0x500 + k % 0x100, k.to_bytes(2, "big") + bytes([0x5A])) for k in range(n)]
    for m in ret:
        b1.send(m)
    got = frames(b0, n)
    check("1,000 frames node1 -> node0, none lost, in order",
          list(map(key, got)) == list(map(key, ret)), f"{len(got)} of {n} arrived")

    b2 = bus(host, port, "node2", can_filters=[{"can_id": 0x123, "can_mask": 0x7FF,
                                                "extended": False}])
    b0.send(msg(0x124, [0x77]))
    b0.send(msg(0x123, [0x78]))
    b0.send(msg(0x1FFFF123, [0x79], ext=True))
    got = frames(b2, 2, timeout=3.0)
    check("a receive filter passes only base id 0x123",
          list(map(key, got)) == [(0x123, False, bytes([0x78]))], f"got {got}")
    b2.shutdown()

    b1.shutdown()
    b1 = bus(host, port, "node1")
    b0.send(msg(0x42, [1]))
    got = frames(b1, 1)
    check("a client that reconnects receives again", [key(m) for m in got] == [(0x42, False, b"\x01")],
          f"got {got}")
    b1.send(msg(0x43, [2]))
    got = frames(b0, 1)
    check("a client that reconnects sends again", [key(m) for m in got] == [(0x43, False, b"\x02")],
          f"got {got}")

    c1, c2 = bus(host, port, "node3"), bus(host, port, "node3")
    b0.send(msg(0x44, [3]))
    g1, g2 = frames(c1, 1), frames(c2, 1)
    check("two clients on one bus both receive",
          [key(m) for m in g1] == [key(m) for m in g2] == [(0x44, False, b"\x03")],
          f"got {g1} and {g2}")
    c1.send(msg(0x45, [4]))
    c2.send(msg(0x46, [5]))
    got = sorted(key(m) for m in frames(b0, 2))
    check("two clients on one bus both send",
          got == [(0x45, False, b"\x04"), (0x46, False, b"\x05")], f"got {got}")
    for b in (b0, b1, c1, c2):
        b.shutdown()


def control(host, port, line):
    """Sends one command on a connection of its own; returns the answer."""
    with socket.create_connection((host, port), timeout=30) as s:
        hi = s.recv(64).decode()
        assert hi == "< hi >", hi
        s.sendall(line.encode())
        return s.recv(256).decode()


def cut(host, port):
    b0, b3 = bus(host, port, "node0"), bus(host, port, "node3")
    n, half = 300, 150
    out = [msg(0x300 + k % 0x80, k.to_bytes(2, "big")) for k in range(n)]
    for m in out[:half]:
        b0.send(m)
    got = frames(b3, 50)
    answer = control(host, port, "< fault cut a 2 >")
    check("the fault command is accepted", answer == "< ok >", answer)
    # frames `half`.. are submitted while line A is cut between node1 and node2
    print(f"submitted after the cut: k >= {half}")
    for m in out[half:]:
        b0.send(m)
    got += frames(b3, n - len(got))
    time.sleep(0.5)
    got += frames(b3, 1, timeout=0.5)
    keys = list(map(key, got))
    missing = [k for k in range(n) if key(out[k]) not in keys]
    dups = len(keys) - len(set(keys))
    check("line A cut during traffic: every frame exactly once",
          not missing and dups == 0 and len(keys) == n,
          f"{len(keys)} received, missing {missing[:10]}, {dups} duplicated")
    b0.shutdown()
    b3.shutdown()


def beacon(host, port):
    from can.interfaces.socketcand import detect_beacon

    found = detect_beacon(5000)
    chans = sorted(c["channel"] for c in found)
    check("python-can's beacon detection finds node0..node3",
          chans == ["node0", "node1", "node2", "node3"], f"found {found}")
    check("the beacon names this server",
          all(c["host"] == host and c["port"] == port for c in found), f"found {found}")


def main():
    what, host, port = sys.argv[1], sys.argv[2], int(sys.argv[3])
    {"basic": basic, "cut": cut, "beacon": beacon}[what](host, port)
    print(f"serve_can {what}: {len(PASSED)} checks ok, {len(FAILED)} failing")
    if FAILED:
        sys.exit(1)


if __name__ == "__main__":
    main()
