"""The version of rigidmech, in one place (read by ``rigidmech.__version__`` and the command
line's ``--version``)."""

__all__ = ["__version__"]

__version__ = "0.1.0"
