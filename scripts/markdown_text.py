"""Text from users' specs and scenes (technique labels, scene names, notes) set into the
Markdown the scripts write, escaped so that it reads as itself: the rule of
testbed/core/markdown_text.h, which every Markdown the testbed itself writes goes through.
In a GitHub-flavoured table a '|' splits the cell and a line break ends the table; a
backtick opens a code span, '<' raw HTML, '*', '_', '~', '[' emphasis and links."""

_ESCAPED = set("\\|`*~[]")


def _word(text, i):
    return 0 <= i < len(text) and text[i].isascii() and text[i].isalnum()


def markdown_text(text):
    text = str(text)
    out = []
    for i, c in enumerate(text):
        if c in _ESCAPED or (c == "_" and not (_word(text, i - 1) and _word(text, i + 1))):  # a_b never emphasizes
            out.append("\\" + c)
        elif c == "<":
            out.append("&lt;")
        elif c == "\n":
            out.append("<br>")  # a line break inside a cell, as GitHub renders tables
        elif c == "\r" and text[i + 1:i + 2] == "\n":
            pass  # part of a CRLF line break: the '\n' gives the <br>
        elif ord(c) < 0x20 or ord(c) == 0x7F:
            out.append(" ")
        else:
            out.append(c)
    return "".join(out)


def markdown_code(text):
    """`text` as an inline code span (CommonMark 6.1), '|' kept escaped for tables."""
    body, run, longest = [], 0, 0
    for c in str(text):
        run = run + 1 if c == "`" else 0
        longest = max(longest, run)
        body.append("\\|" if c == "|" else " " if ord(c) < 0x20 or ord(c) == 0x7F else c)
    body = "".join(body)
    fence = "`" * (longest + 1)
    pad = " " if body and (body[0] == "`" or body[-1] == "`") else ""
    return fence + pad + body + pad + fence
