"""MathML a page may carry: ``latex2mathml``'s tree passed through an
allow-list of elements and attributes, every text escaped.

``latex2mathml`` turns ``\\href{javascript:…}{x}`` and ``\\style{…}{x}`` into
``href`` and ``style`` attributes, and its string output un-escapes the text
of an element, so ``\\text{<script>…}`` becomes a live ``<script>`` inside
``<mtext>``. The formulas of a component file are the user's text, so the page
takes the converter's element tree instead, keeps only MathML Core's
presentation elements and their layout attributes (values of letters, digits,
``#``, ``.``, ``%``, ``+``, ``-`` and spaces: no ``:``, so no address and no
style), and serializes it with every text escaped; only the converter's own
numeric character references (``&#x0003C;``) are kept as references.
"""
from __future__ import annotations

import re
from xml.etree.ElementTree import Element, tostring

__all__ = ["ELEMENTS", "ATTRIBUTES", "safe_mathml"]

#: MathML presentation elements the page keeps.
ELEMENTS = frozenset(
    "math mrow mi mn mo ms mtext mspace msub msup msubsup munder mover munderover mfrac "
    "msqrt mroot mstyle mpadded mphantom menclose mtable mtr mtd mmultiscripts "
    "mprescripts none merror semantics mfenced".split())
#: Their attributes the page keeps (layout only: no address, style or handler).
ATTRIBUTES = frozenset(
    "display mathvariant stretchy fence separator lspace rspace accent accentunder "
    "movablelimits largeop symmetric minsize maxsize form linethickness columnalign "
    "columnspacing columnlines rowalign rowspacing rowlines frame framespacing "
    "equalrows equalcolumns displaystyle scriptlevel width height depth voffset "
    "notation open close separators mathsize mathcolor mathbackground columnspan "
    "rowspan".split())
_VALUE = re.compile(r"[A-Za-z0-9#.%+\- ]*")
_REFERENCE = re.compile(r"&amp;(#x?[0-9A-Fa-f]{1,6};)")
_MATHML = "http://www.w3.org/1998/Math/MathML"


def _clean(element: Element) -> None:
    """Drop, below ``element``, every attribute and element not allowed; an
    element not allowed leaves its text as an ``mtext``."""
    for name in list(element.attrib):
        value = element.attrib[name]
        keep = (name in ATTRIBUTES and _VALUE.fullmatch(value)
                or (name == "xmlns" and element.tag == "math" and value == _MATHML))
        if not keep:
            del element.attrib[name]
    for k, child in enumerate(list(element)):
        if child.tag in ELEMENTS:
            _clean(child)
            continue
        text = Element("mtext")
        text.text = "".join(child.itertext())
        text.tail = child.tail
        element[k] = text


def safe_mathml(math: Element) -> str:
    """``math`` (``latex2mathml.converter.convert_to_element``) as MathML text,
    allow-listed and escaped (see the module docstring).

    Parameters
    ----------
    math : xml.etree.ElementTree.Element
        The converter's ``<math>`` element; it is cleaned in place.

    Examples
    --------
    >>> from latex2mathml.converter import convert_to_element
    >>> safe_mathml(convert_to_element(r"\\text{<b>}", xmlns=""))
    '<math display="inline"><mrow><mtext>&lt;b&gt;</mtext></mrow></math>'
    """
    if math.tag != "math":
        raise ValueError(f"safe_mathml: a <math> element, not <{math.tag}>")
    _clean(math)
    return _REFERENCE.sub(r"&\1", tostring(math, encoding="unicode"))
