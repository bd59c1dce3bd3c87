"""A griffe extension for the API reference: the docstrings are written for
Sphinx (``:class:`Grid```, ``:meth:`branch_map```, double backticks,
``>>>`` examples), and mkdocstrings renders Markdown. This turns each role
into inline code with the name as written (a name with a leading ``~``
shows its last part) and each ``>>>`` example into a fenced code block, so
that the pages read as the stub does. Loaded by mkdocs.yml
(``extensions: [docs/griffe_roles.py]``)."""

from __future__ import annotations

import re
from typing import Any

import griffe

_ROLE = re.compile(r":(?:py:)?(?:class|meth|func|attr|mod|data|exc|obj|const)::?`~?([^`]+)`")


def _code(match: "re.Match[str]") -> str:
    name = match.group(1)
    if match.group(0).split("`")[1].startswith("~"):
        name = name.rsplit(".", 1)[-1]
    return f"`{name}`"


def _fence_examples(text: str) -> str:
    """Each run of ``>>>`` lines and their output (up to a blank line) as a
    fenced ``pycon`` block."""
    out, block = [], []
    for line in text.split("\n") + [""]:
        if block and line.strip():
            block.append(line)
            continue
        if block:
            indent = min(len(b) - len(b.lstrip()) for b in block)
            out += ["```pycon", *(b[indent:] for b in block), "```"]
            block = []
        if line.lstrip().startswith(">>>"):
            block.append(line)
        else:
            out.append(line)
    return "\n".join(out[:-1])


def markdown_of(text: str) -> str:
    """``text`` with its Sphinx roles as inline code and its examples fenced."""
    return _fence_examples(_ROLE.sub(_code, text))


class SphinxRoles(griffe.Extension):
    """Rewrites the Sphinx roles of every docstring griffe loads."""

    def on_instance(self, *, obj: griffe.Object, **kwargs: Any) -> None:
        if obj.docstring is not None:
            obj.docstring.value = markdown_of(obj.docstring.value)
