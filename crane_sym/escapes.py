"""Text from a file, escaped for where it lands outside Markdown and HTML
(:mod:`crane_sym.markdown` and :mod:`crane_sym.docs.safe_mathml` cover those):
a terminal, and Matplotlib's text, which sets what stands between two ``$``
as mathtext.

A component file's title is the user's text: printed raw, an escape code in
it (``ESC [ 2 J``) would drive the terminal; drawn raw, ``$\\input{x}$`` fails
the plot with Matplotlib's parser error.
"""
from __future__ import annotations

import re

__all__ = ["mathtext_text", "terminal_text"]

#: C0 and C1 control characters and DEL; a tab and a line break are kept.
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")


def terminal_text(text: object) -> str:
    """``text`` with every control character written as its escape (``\\x1b``),
    so that printing it cannot drive the terminal.

    Parameters
    ----------
    text : object
        What is to be printed; not a string: as ``str`` writes it.

    Examples
    --------
    >>> terminal_text("red \\x1b[31m")
    'red \\\\x1b[31m'
    """
    return _CONTROL.sub(lambda m: f"\\x{ord(m.group()):02x}", str(text))


def mathtext_text(text: object) -> str:
    """``text`` as literal Matplotlib text: its control characters escaped
    (:func:`terminal_text`) and every ``$`` written ``\\$``, so that no part
    of it is read as mathtext.

    Parameters
    ----------
    text : object
        A title or label that is not mathtext.

    Examples
    --------
    >>> print(mathtext_text("cost $5 and $x$"))
    cost \\$5 and \\$x\\$
    """
    return terminal_text(text).replace("$", "\\$")
