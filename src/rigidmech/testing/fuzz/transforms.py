"""Metamorphic transformations of a :class:`~rigidmech.testing.fuzz.Model`.

Each gives the same mechanism described differently, with the relation its accelerations
must keep (book, ch. 18: the fundamental principle holds in every Galilean frame and in
every consistent system of units):

* :func:`turned_ground`: the whole scene (ground parts, gravity, forces) turned and moved
  relative to the Galilean frame by a constant displacement: the same q'' (the coordinates
  are relative ones);
* :func:`reordered`: the bodies connected in another order (parents still first), the
  actions and knife edges given in reverse order: the same q'';
* :func:`renamed`: the coordinates renamed: the same q'' under the new names;
* :func:`scaled`: lengths times ``length``, masses times ``mass``, times times ``time``
  (every constant scaled by its dimension, radii, knife edges and the closing joint's point
  included): a coordinate of length scales by ``length``, its rate by ``length / time``, its
  acceleration by ``length / time**2``; an angle is unchanged, its rate scales by
  ``1 / time`` and its acceleration by ``1 / time**2``.

Examples
--------
>>> from rigidmech.testing.fuzz import BodySpec, Model
>>> m = Model(bodies=(BodySpec(name="b0", parent=-1, joint="cylindrical"),))
>>> scaled(m, length=2.0, mass=1.0, time=1.0)[1]
{'q_b0_0': (1.0, 1.0, 1.0), 'q_b0_1': (2.0, 2.0, 2.0)}
"""

from __future__ import annotations

from dataclasses import replace

from .description import Model, coordinate_kinds

__all__ = ["turned_ground", "reordered", "renamed", "scaled"]


def turned_ground(model: Model, rotations, origin) -> Model:
    """``model`` with its ground frame turned by the constant ``rotations``
    (``(axis index, angle)``, body-fixed) and moved to ``origin`` in the Galilean frame.

    Examples
    --------
    >>> from rigidmech.testing.fuzz import BodySpec, Model
    >>> m = Model(bodies=(BodySpec(name="b0", parent=-1, joint="pivot"),))
    >>> turned_ground(m, ((0, 0.5),), (1.0, 0.0, 0.0)).ground
    ((0, 0.5),)
    """
    return replace(model, ground=tuple(rotations), ground_origin=tuple(origin))


def renamed(model: Model, prefix: str) -> Model:
    """``model`` with its coordinates named ``{prefix}_{body}_{k}``."""
    return replace(model, prefix=prefix)


def reordered(model: Model, order) -> Model:
    """``model`` with its bodies in the order ``order`` (a permutation of their indices in
    which every parent comes before its children) and its actions in reverse order.

    Examples
    --------
    >>> from rigidmech.testing.fuzz import BodySpec, Model
    >>> m = Model(bodies=(BodySpec(name="a", parent=-1, joint="pivot"),
    ...                   BodySpec(name="b", parent=-1, joint="prismatic")))
    >>> [b.name for b in reordered(m, (1, 0)).bodies]
    ['b', 'a']
    """
    order = tuple(order)
    if sorted(order) != list(range(len(model.bodies))):
        raise ValueError(f"`order` must be a permutation of the body indices; got {order}.")
    new = {old: k for k, old in enumerate(order)}

    def index(k):
        return -1 if k < 0 else new[k]

    bodies = tuple(replace(model.bodies[old], parent=index(model.bodies[old].parent))
                   for old in order)

    def moved(specs, *fields):
        return tuple(replace(s, **{f: index(getattr(s, f)) for f in fields})
                     for s in reversed(specs))

    closure = model.closure
    if closure is not None:
        closure = replace(closure, body=new[closure.body],
                          assembly=tuple(closure.assembly[old] for old in order))
    return replace(
        model, bodies=bodies, closure=closure, knives=moved(model.knives, "body"),
        springs=moved(model.springs, "body_a", "body_b"),
        dampers=moved(model.dampers, "body_a", "body_b"), torques=moved(model.torques, "body"),
        forces=moved(model.forces, "body"),
        torsional_dampers=moved(model.torsional_dampers, "body"))


def scaled(model: Model, *, length=1.0, mass=1.0, time=1.0):
    """``model`` in other units, and for each coordinate the factors (q, q', q'') between
    the new values and the old ones.

    Powers of two keep every number of the grid exact.
    """
    L, M, T = float(length), float(mass), float(time)

    def v(xyz, f):
        return tuple(x * f for x in xyz)

    bodies = tuple(replace(
        b, at=v(b.at, L), centre=v(b.centre, L), mass=b.mass * M, pitch=b.pitch * L,
        inertia=v(b.inertia, M * L * L), radius=b.radius * L) for b in model.bodies)
    force, moment = M * L / T**2, M * L * L / T**2
    out = replace(
        model, bodies=bodies,
        gravity=None if model.gravity is None else v(model.gravity, L / T**2),
        springs=tuple(replace(s, a=v(s.a, L), b=v(s.b, L), k=s.k * M / T**2, l0=s.l0 * L)
                      for s in model.springs),
        dampers=tuple(replace(d, a=v(d.a, L), b=v(d.b, L), c=d.c * M / T)
                      for d in model.dampers),
        torques=tuple(replace(c, moment=v(c.moment, moment)) for c in model.torques),
        forces=tuple(replace(f, vector=v(f.vector, force), at=v(f.at, L))
                     for f in model.forces),
        torsional_dampers=tuple(replace(d, c=d.c * M * L * L / T)
                                for d in model.torsional_dampers),
        knives=tuple(replace(k, at=v(k.at, L)) for k in model.knives),
        ground_origin=v(model.ground_origin, L))
    if model.closure is not None:
        assembly = tuple(tuple(x * L if kind == "l" else x for x, kind in
                               zip(values, b.joint_kinds, strict=True))
                         for values, b in zip(model.closure.assembly, model.bodies,
                                              strict=True))
        out = replace(out, closure=replace(model.closure, meets=v(model.closure.meets, L),
                                           assembly=assembly))
    factors = {n: (L, L / T, L / T**2) if kind == "l" else (1.0, 1.0 / T, 1.0 / T**2)
               for n, kind in coordinate_kinds(model).items()}
    return out, factors
