"""The public errors module and the typing marker (issue 9, "Public errors")."""

import inspect
import pathlib
import tomllib

import rigidmech
import rigidmech._core.errors as core_errors
import rigidmech.errors as errors

ROOT = pathlib.Path(__file__).resolve().parents[1]


def test_every_error_class_is_public_and_the_same_object():
    defined = {name for name, obj in vars(core_errors).items()
               if inspect.isclass(obj) and issubclass(
                   obj, core_errors.RigidmechError | core_errors.RigidmechWarning)}
    assert set(errors.__all__) == defined
    for name in defined:
        assert getattr(errors, name) is getattr(core_errors, name)
    assert rigidmech.errors is errors


def test_specific_errors_subclass_a_builtin():
    for name in errors.__all__:
        cls = getattr(errors, name)
        if cls in (errors.RigidmechError, errors.RigidmechWarning):
            continue
        if issubclass(cls, Warning):  # warnings: rigidmech's, and a builtin category
            assert issubclass(cls, errors.RigidmechWarning), name
            assert issubclass(cls, RuntimeWarning | UserWarning), name
            continue
        assert issubclass(cls, errors.RigidmechError)
        assert issubclass(cls, ValueError | TypeError | ArithmeticError), name


def test_py_typed_ships_with_the_package():
    package = pathlib.Path(rigidmech.__file__).parent
    assert (package / "py.typed").is_file()
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert "py.typed" in config["tool"]["setuptools"]["package-data"]["rigidmech"]


def test_errors_page_in_the_docs():
    page = (ROOT / "docs" / "api" / "errors.rst").read_text()
    assert "automodule:: rigidmech.errors" in page
