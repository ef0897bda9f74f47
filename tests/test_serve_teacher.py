"""The teacher's page of ``--serve --records DIR`` (issue 41): ``/teacher`` shows the class's
records live, with a token of its own printed once at start; without it, or with the class's
token, it answers 403.  A real server on a free local port (tests/served.py)."""

from __future__ import annotations

import asyncio
import re
from pathlib import Path

import aiohttp
import pytest

from tests.helpers import MAPS
from tests.served import served
from tui_search.engine.course.records import Writer
from tui_search.serve.teacher import teacher_html, teacher_refusal, teacher_token

TUTORIAL = str(MAPS / "tutorial.txt")
TEACHER = re.compile(r"^http://\S+/teacher\?key=([A-Za-z0-9_-]+)$", re.MULTILINE)
pytestmark = pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="reads /proc")


def test_the_teachers_token_is_its_own_and_compared_whole() -> None:
    token = teacher_token("class-token-xxxxxxxx")
    assert token != "class-token-xxxxxxxx" and len(token) >= 24
    assert teacher_refusal(token, token, "class-token-xxxxxxxx") is None
    assert teacher_refusal(None, token, None) is not None
    assert teacher_refusal(token[:-1], token, None) is not None
    assert teacher_refusal(token + "x", token, None) is not None
    assert "class's link" in teacher_refusal("class-token-xxxxxxxx", token,
                                             "class-token-xxxxxxxx")


def test_the_page_escapes_what_the_visitors_wrote(tmp_path: Path) -> None:
    Writer(tmp_path, "<script>alert(1)</script>").write("quiz", algorithm="bfs", right=True)
    page = teacher_html(str(tmp_path), "tutorial")
    assert "<script>alert" not in page and "&lt;script&gt;alert(1)&lt;/script&gt;" in page


async def get(url: str, host: str | None = None) -> tuple[int, str]:
    headers = {"Host": host} if host else {}
    async with aiohttp.ClientSession() as session, session.get(url, headers=headers) as got:
        return got.status, await got.text()


def test_teacher_needs_its_own_token_and_shows_the_records_as_they_arrive(tmp_path) -> None:
    records = tmp_path / "records"
    with served("--records", str(records), "--host", "0.0.0.0", TUTORIAL) as server:
        links = TEACHER.findall(server.banner)
        assert len(links) == 1, server.banner  # printed once, on a line of its own
        key = links[0]
        assert server.token is not None and key != server.token
        base = server.url + "teacher"
        assert asyncio.run(get(base))[0] == 403
        assert asyncio.run(get(f"{base}?key={server.token}"))[0] == 403  # the class's token
        assert asyncio.run(get(f"{base}?token={server.token}"))[0] == 403
        assert asyncio.run(get(f"{base}?key={key[:-1]}"))[0] == 403
        port = server.url.rsplit(":", 1)[1].strip("/")
        assert asyncio.run(get(f"{base}?key={key}", host=f"evil.example:{port}"))[0] == 403
        status, page = asyncio.run(get(f"{base}?key={key}"))
        assert status == 200 and "0 students" in page and "none recorded" in page
        Writer(records, "Ada", "a1b2c3").write("by_hand", algorithm="bfs", finished=True,
                                                 steps=22, mistakes=1, by_cause={"newest": 1})
        status, page = asyncio.run(get(f"{base}?key={key}"))
        assert status == 200 and "<td>Ada</td>" in page
        assert "1 of 1 student took the newest entry in BFS at least once" in page
        status, visitor_page = asyncio.run(get(server.page))  # a visitor's page
        assert status == 200 and key not in visitor_page


def test_without_records_there_is_no_teachers_page() -> None:
    with served(TUTORIAL) as server:
        assert "/teacher" not in server.banner
        assert asyncio.run(get(server.url + "teacher"))[0] == 404
