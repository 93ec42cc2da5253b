"""Templates of a family of designs: one derived model per structure, whose
Lagrange's equations, lambdified forms and system tables the designs of that
structure share.

A design of a sweep differs from its template only in its parts' values (a
stiffness, a mass, a hold time); what rests on anything else (which parts,
their kinds and names, whether a link has a gap, how many steps a
characteristic takes: :func:`structure`) is derived once, the first time the
structure is met, and every design of it takes the template's derivation
(:meth:`crane_sym.components.model.Model.with_parts`). A component file's
designs (:mod:`crane_sym.components.designs`) and a paper's drive train (003's
``drive_train.py``) both take their designs from :class:`Templates`.
"""
from __future__ import annotations

from typing import Sequence

from crane_sym.components import kinds
from crane_sym.components.model import Model
from crane_sym.components.parts import Component
from crane_sym.components.pruning import Scope

__all__ = ["Templates", "structure"]


def structure(parts: Sequence[Component]) -> tuple:
    """What a model's derivation rests on beside its parts' values, which
    :meth:`Model.with_parts` cannot change: each part's kind and name, whether
    an elastic link has a gap, how many steps a characteristic takes (each
    kind's ``shape``).

    Parameters
    ----------
    parts : sequence of Component
        The parts of a model.
    """
    by_kind = {k.part_kind: k for k in kinds.KINDS}      # kinds.of, once per kind
    out = []
    for p in parts:
        shape = by_kind[p.kind].shape
        out.append((type(p).__name__, p.name, shape(p) if shape is not None else None))
    return tuple(out)


class Templates:
    """One derived model per :func:`structure`, the template of every design of
    it: a design is its template with the design's parts
    (:meth:`Model.with_parts`: assembled anew, Lagrange's equations and their
    lambdified form shared, not derived again), its name, title and scope the
    template's. A structure met for the first time is derived once, as
    ``Model(parts, name, title, scope)``.

    Parameters
    ----------
    name, title : str
        The name and title of the models.
    scope : Scope, optional
        The run the models are built for (``Model.for_run``), if any.
    models : sequence of Model, optional
        Templates derived already (a component file's own model).
    """

    def __init__(self, name: str, title: str = "", scope: Scope | None = None,
                 models: Sequence[Model] = ()) -> None:
        self.name, self.title, self.scope = name, title, scope
        self.models = {structure(m.components): m for m in models}

    def design(self, parts: Sequence[Component]) -> Model:
        """The model of ``parts``, its derivation its structure's template's.

        Parameters
        ----------
        parts : sequence of Component
            The design's parts.
        """
        key = structure(parts)
        if key not in self.models:
            self.models[key] = Model(parts, self.name, self.title, self.scope)
        return self.models[key].with_parts(parts)
