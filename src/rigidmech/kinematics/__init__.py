"""Part II of the book, kinematics (ch. 6-10): solids, kinematic torsors, composition."""

from .solid import KinematicTorsor, Solid, kinematic_torsor

__all__ = ["KinematicTorsor", "Solid", "kinematic_torsor"]
