"""The teacher's page of ``--serve --records DIR``: ``/teacher``, the class's table (a student
a row, then the misconceptions) read from the records folder at each request, the page
reloading itself every few seconds as records arrive.

Visitors carry the class's token in their links, so the page has **a token of its own**
(:func:`teacher_token`): printed once at start, on a line of its own, never the class's,
never in a visitor's page.  :func:`teacher_refusal` compares it in constant time; without it,
or with the class's token, the page answers 403.  The page is plain HTML, every name and word
from the records escaped (they are the visitors').
"""

from __future__ import annotations

import asyncio
import html
import secrets
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from tui_search.serve.guard import Guard

#: The page's path, and the query parameter its token goes in.
PATH = "/teacher"
KEY = "key"
#: The page reloads itself this often (seconds).
REFRESH = 5


def teacher_token(class_token: str | None) -> str:
    """A random token for the teacher's page, never the class's."""
    while True:
        token = secrets.token_urlsafe(24)
        if token != class_token:
            return token


def teacher_refusal(given: str | None, token: str, class_token: str | None) -> str | None:
    """Why a request for the page is refused (one line), or None: ``given`` must be the
    teacher's ``token`` (compared in constant time), and is never the class's."""
    if not given:
        return "the teacher's page needs its own link (printed once when the server started)"
    data = given.encode()
    if class_token is not None and secrets.compare_digest(data, class_token.encode()):
        return "the class's link does not open the teacher's page"
    if not secrets.compare_digest(data, token.encode()):
        return "the teacher's page needs its own link (printed once when the server started)"
    return None


def teacher_url(base: str, token: str) -> str:
    """The page's link, from the server's address (``http://host:port``)."""
    return f"{base}{PATH}?{KEY}={token}"


def teacher_html(folder: str, title: str) -> str:
    """The page: the class table of ``folder``'s records, as HTML."""
    from tui_search.engine.course.class_table import class_table
    from tui_search.engine.course.records import RecordsError, read_records

    e = html.escape
    try:
        events, warnings = read_records(folder)
    except RecordsError as exc:
        events, warnings = [], [str(exc)]
    table = class_table(events)
    rows = []
    for r in table.rows:
        mistakes = ", ".join(f"{e(cause)} {n}" for cause, n in sorted(
            r.mistakes.items(), key=lambda item: (-item[1], item[0])))
        rows.append(
            "<tr>" + "".join(f"<td>{cell}</td>" for cell in (
                e(r.student), e(", ".join(r.solved)) or ("none" if r.tried else ""),
                f"{r.quiz_right} of {r.quiz_asked}" if r.quiz_asked else "",
                f"{r.runs_finished} of {r.runs} finished" if r.runs else "",
                mistakes or ("none" if r.runs else ""),
                f"{r.checks_matched} of {r.checks}" if r.checks else "", e(r.last))) + "</tr>")
    of = len(table.rows)
    misconceptions = "".join(f"<li>{e(m.sentence(of))}</li>" for m in table.misconceptions)
    warned = "".join(f"<li>{e(w)}</li>" for w in warnings[:50])
    head = ("student", "exercises solved", "quiz", "by hand", "mistakes by kind",
            "traces matched", "last record")
    return f"""<!doctype html>
<html lang="en"><head><meta charset="utf-8">
<meta http-equiv="refresh" content="{REFRESH}">
<meta name="referrer" content="no-referrer">
<title>tui-search: the class ({e(title)})</title>
<style>body{{font-family:sans-serif;margin:1.5em}}table{{border-collapse:collapse}}
td,th{{border:1px solid #999;padding:.25em .6em;text-align:left}}th{{background:#eee}}</style>
</head><body>
<h1>The class: {e(title)}</h1>
<p>{of} student{"s" if of != 1 else ""}, {len(events):,} records; this page reloads every
{REFRESH} seconds.</p>
<table id="class"><tr>{"".join(f"<th>{h}</th>" for h in head)}</tr>
{"".join(rows)}</table>
<h2>Misconceptions</h2>
<ul id="misconceptions">{misconceptions or "<li>none recorded</li>"}</ul>
{f'<h2>Lines skipped</h2><ul id="warnings">{warned}</ul>' if warned else ""}
</body></html>
"""


def teacher_routes_of(guard: Guard, records: str | None, token: str | None, title: str
                      ) -> tuple[Guard, str | None, list[Any]]:
    """The server's guard, the page's token and its route: with ``records``, the page at
    :data:`PATH` (its token ``token``, else a random one), which the guard leaves to check
    its own token; without, the guard as it is, no token, no route."""
    if records is None:
        return guard, None, []
    from aiohttp import web

    key = token or teacher_token(guard.token)
    class_token = guard.token

    async def page(request: web.Request) -> web.StreamResponse:
        why = teacher_refusal(request.query.get(KEY), key, class_token)
        if why is not None:  # (returned: the guard makes a raised 403 a folder's 404)
            return web.Response(status=403, text=why)
        text = await asyncio.to_thread(teacher_html, records, title)
        return web.Response(text=text, content_type="text/html", headers={
            "Cache-Control": "no-store", "Referrer-Policy": "no-referrer"})

    return (guard._replace(own_paths=frozenset({PATH})), key,
            [web.get(PATH, page, name="teacher")])


__all__ = ["KEY", "PATH", "teacher_html", "teacher_refusal", "teacher_routes_of", "teacher_token",
           "teacher_url"]
