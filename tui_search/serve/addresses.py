"""This computer's own addresses, for the links a server on every network prints
(``--serve --host 0.0.0.0``): each network interface's, the loopback last.

Standard library only.  On Linux each interface's IPv4 address comes from the kernel
(``SIOCGIFADDR`` on each of :func:`socket.if_nameindex`'s names) and its IPv6 ones from
``/proc/net/if_inet6``; elsewhere, the addresses the computer's name resolves to and the one
its route out uses.  Link-local IPv6 addresses (``fe80::``) are left out: a browser cannot open
them without naming the interface.
"""

from __future__ import annotations

import ipaddress
import socket
import struct
import sys
from typing import NamedTuple

#: ``SIOCGIFADDR``: Linux's ioctl for an interface's IPv4 address.
_SIOCGIFADDR = 0x8915
_IF_INET6 = "/proc/net/if_inet6"


class Address(NamedTuple):
    """One address of this computer, and the interface it is on ("" when not known)."""

    ip: str
    interface: str = ""

    @property
    def is_loopback(self) -> bool:
        return ipaddress.ip_address(self.ip).is_loopback


def own_addresses(family: socket.AddressFamily = socket.AF_INET) -> list[Address]:
    """This computer's addresses of ``family`` (IPv4 or IPv6), each once, in the interfaces'
    order, the loopback ones last; never empty (at worst the loopback)."""
    found: list[Address] = []
    if sys.platform.startswith("linux"):
        found = _linux_ipv4() if family == socket.AF_INET else _linux_ipv6()
    if not any(not a.is_loopback for a in found):
        found += _by_name_and_route(family)
    found.append(Address("127.0.0.1" if family == socket.AF_INET else "::1", "lo"))
    return loopback_last(found)


def loopback_last(addresses: list[Address]) -> list[Address]:
    """``addresses`` each once (the first seen), link-local ones left out, loopback last."""
    seen: set[str] = set()
    kept: list[Address] = []
    for a in addresses:
        ip = ipaddress.ip_address(a.ip)
        if a.ip not in seen and not ip.is_link_local and not ip.is_unspecified:
            seen.add(a.ip)
            kept.append(a)
    return sorted(kept, key=lambda a: a.is_loopback)  # stable: the interfaces' order kept


def _linux_ipv4() -> list[Address]:
    import fcntl

    found = []
    try:
        names = [name for _, name in socket.if_nameindex()]
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            for name in names:
                request = struct.pack("256s", name.encode()[:15])
                try:
                    answer = fcntl.ioctl(s.fileno(), _SIOCGIFADDR, request)
                except OSError:  # no IPv4 address on this interface
                    continue
                found.append(Address(socket.inet_ntoa(answer[20:24]), name))
    except OSError:
        return []
    return found


def _linux_ipv6() -> list[Address]:
    found = []
    try:
        with open(_IF_INET6, encoding="ascii") as lines:
            for line in lines:  # address (32 hex digits), index, prefix, scope, flags, name
                fields = line.split()
                if len(fields) == 6 and len(fields[0]) == 32:
                    ip = ipaddress.IPv6Address(bytes.fromhex(fields[0]))
                    found.append(Address(str(ip), fields[5]))
    except (OSError, ValueError):
        return []
    return found


def _by_name_and_route(family: socket.AddressFamily) -> list[Address]:
    """Where no interface can be asked: the computer's name's addresses and the address its
    route out uses (a datagram socket "connected" sends nothing)."""
    found = []
    try:
        for *_, sockaddr in socket.getaddrinfo(socket.gethostname(), None, family):
            found.append(Address(str(sockaddr[0])))
    except OSError:
        pass
    out = "192.0.2.1" if family == socket.AF_INET else "2001:db8::1"  # documentation nets
    try:
        with socket.socket(family, socket.SOCK_DGRAM) as s:
            s.connect((out, 9))
            found.insert(0, Address(str(s.getsockname()[0])))
    except OSError:
        pass
    return found
