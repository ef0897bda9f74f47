"""Who may talk to ``tui-search --serve``: the checks every request passes before textual-serve
sees it (an aiohttp middleware, :meth:`Guard.middleware`).

* **Host** (against DNS rebinding: another site's name made to point at this computer, so a
  page there could drive the apps): only the names the server was started for --
  ``localhost``, ``127.0.0.1``, ``::1`` and ``--host``'s value; served on every network
  (``0.0.0.0``, ``::``) also this computer's name and any IP address (an address is not a
  name another site can re-point).  A page's ``Origin``, when sent, must be the page's own
  host.  Anything else gets 403.
* **Token**, unless the server listens on loopback only: a random one, printed in the URL
  (``?token=...``, as Jupyter does), then kept in a cookie so the page's further requests and
  its websocket carry it.  A request without it gets 403 -- but for the paths with a token
  of their own (``own_paths``: the teacher's page, :mod:`tui_search.serve.teacher`), which
  check theirs.

textual-serve's static folder is served without its directory listing (in
:mod:`tui_search.serve.web`, where the routes are made); a folder is "not found" (404) here.
"""

from __future__ import annotations

import ipaddress
import secrets
import socket
from collections.abc import Awaitable, Callable
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    from aiohttp import web
    from aiohttp.typedefs import Middleware

COOKIE = "tui_search_token"
LOOPBACK_NAMES = ("localhost", "127.0.0.1", "::1")
EVERY_NETWORK = ("0.0.0.0", "::", "")

Handler = Callable[["web.Request"], Awaitable["web.StreamResponse"]]


def is_loopback(host: str) -> bool:
    """Does ``host`` (a name or an address) reach this computer only?"""
    if host.lower() == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def host_name(header: str) -> str:
    """The name in a ``Host`` header (or an origin's host), without its port, lower case."""
    header = header.strip().lower()
    if header.startswith("["):
        return header[1:].split("]", 1)[0]
    if header.count(":") == 1:
        header = header.split(":", 1)[0]
    return header.rstrip(".")


class Guard(NamedTuple):
    """The names accepted in ``Host``, whether any IP address is, and the token (or None)."""

    names: frozenset[str]
    any_address: bool = False
    token: str | None = None
    own_paths: frozenset[str] = frozenset()  # paths that check a token of their own

    @classmethod
    def for_host(cls, host: str, token: str | None = None) -> Guard:
        """The guard of a server listening on ``host``: a token unless it is loopback --
        ``token`` (the servers of one class behind one proxy share it), else a random one."""
        names = {*LOOPBACK_NAMES, host_name(host)}
        every = host in EVERY_NETWORK
        if every:
            names |= {socket.gethostname().lower(), socket.getfqdn().lower()}
        chosen = None if is_loopback(host) else token or secrets.token_urlsafe(18)
        return cls(frozenset(names - {""}), every, chosen)

    def host_allowed(self, header: str) -> bool:
        name = host_name(header)
        if name in self.names:
            return True
        if not self.any_address:
            return False
        try:
            ipaddress.ip_address(name)
        except ValueError:
            return False
        return True

    def refusal(self, request: web.Request) -> str | None:
        """Why ``request`` is refused (one line), or None."""
        if not self.host_allowed(request.host):
            return "this server answers to the addresses it was started for only"
        origin = request.headers.get("Origin")
        if origin is not None and origin.split("://", 1)[-1].lower() != request.host.lower():
            return "another site's page may not use this server"
        if request.path in self.own_paths:
            return None
        if self.token is not None and not (self._given(request.query.get("token"))
                                           or self._given(request.cookies.get(COOKIE))):
            return "open the link the server printed when it started (with its ?token=)"
        return None

    def _given(self, token: str | None) -> bool:
        return (token is not None and self.token is not None
                and secrets.compare_digest(token.encode(), self.token.encode()))

    def middleware(self) -> Middleware:
        """The aiohttp middleware: 403 with :meth:`refusal`'s reason, else the handler's
        response, with the token's cookie when the token came in the URL."""
        from aiohttp import web

        @web.middleware
        async def guard(request: web.Request, handler: Handler) -> web.StreamResponse:
            why = self.refusal(request)
            if why is not None:
                raise web.HTTPForbidden(text=why)
            try:
                response = await handler(request)
            except web.HTTPForbidden:  # aiohttp's answer for a static folder, listing off
                raise web.HTTPNotFound() from None
            if (self.token is not None and self._given(request.query.get("token"))
                    and not response.prepared):
                response.set_cookie(COOKIE, self.token, httponly=True, samesite="Strict")
            return response

        return guard
