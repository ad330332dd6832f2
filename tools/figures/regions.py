"""The regions of the pages a section replaces, between its markers."""
from __future__ import annotations

import re

from .project import FiguresError


def _marker_re(name: str, which: str) -> re.Pattern:
    return re.compile(r"^<!-- figures:" + re.escape(name) + r" " + which + r"\b[^\n]*-->[ \t]*$", re.M)


def begin_marker(name: str, section: str) -> str:
    return f"<!-- figures:{name} begin (tools/figures.sh {section}) -->"


def end_marker(name: str) -> str:
    return f"<!-- figures:{name} end -->"


def find_region(text: str, name: str, section: str, file: str) -> tuple[int, int]:
    """The span of region NAME's body (between the end of its begin line and the start of its end
    line; for an inline region, between its markers). A region that is missing, doubled or
    unclosed is an error naming the section."""
    if is_inline(text, name):
        found = find_inline(text, name, section, file)
        return found.start(1), found.end(1)
    begins = list(_marker_re(name, "begin").finditer(text))
    ends = list(_marker_re(name, "end").finditer(text))
    how = (f"add the lines '{begin_marker(name, section)}' and '{end_marker(name)}' where its figures belong, or "
           f"inside a sentence '{inline_marker(name, 'tools/figures.sh ' + section)}...{end_marker(name)}' on one line")
    if not begins and not ends:
        raise FiguresError(f"{file}: no region 'figures:{name}' for section '{section}': {how}")
    if len(begins) != 1 or len(ends) != 1:
        raise FiguresError(f"{file}: region 'figures:{name}' of section '{section}' has {len(begins)} begin and "
                           f"{len(ends)} end markers; it needs one of each")
    if ends[0].start() < begins[0].end():
        raise FiguresError(f"{file}: region 'figures:{name}' of section '{section}' ends before it begins")
    return begins[0].end() + 1, ends[0].start()


def _inline_re(name: str) -> re.Pattern:
    return re.compile(r"<!-- figures:" + re.escape(name) + r" inline\b[^\n]*?-->([^\n]*?)<!-- figures:"
                      + re.escape(name) + r" end -->")


def inline_marker(name: str, stamp: str) -> str:
    return f"<!-- figures:{name} inline ({stamp}) -->"


def is_inline(text: str, name: str) -> bool:
    return bool(_inline_re(name).search(text)) and not _marker_re(name, "begin").search(text)


def find_inline(text: str, name: str, section: str, file: str) -> re.Match:
    """Inline region NAME, markers included (group 1: its body); an error unless it is there once."""
    found = list(_inline_re(name).finditer(text))
    if len(found) != 1:
        raise FiguresError(f"{file}: inline region 'figures:{name}' of section '{section}' is there "
                           f"{len(found)} times; it needs to be there once")
    return found[0]


def replace_regions(text: str, bodies: dict[str, str], section: str, file: str, inline_stamp: str = "") -> str:
    """TEXT with the body of each region in BODIES replaced; everything else is left as it was. An
    inline region's body must be one line; its marker gets INLINE_STAMP."""
    for name, body in bodies.items():
        if is_inline(text, name):
            m = find_inline(text, name, section, file)
            if "\n" in body.strip():
                raise FiguresError(f"section '{section}': the body of inline region 'figures:{name}' is not one line")
            text = (text[:m.start()] + inline_marker(name, inline_stamp or section) + body.strip()
                    + end_marker(name) + text[m.end():])
            continue
        start, end = find_region(text, name, section, file)
        body = body.strip("\n") + "\n"
        text = text[:start] + body + text[end:]
    return text
