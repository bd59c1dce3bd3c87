"""Shared fixtures: the built-in example task, its driven crank and view."""

import pytest

import burmester

#: The example's poses (x, y, angle in radians), driven center and view.
POSES = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]
C0 = (4.0, -1.0)
VP = (-8.0, 8.0, -8.0, 8.0)


@pytest.fixture
def task():
    """The example task."""
    return burmester.Task(POSES)


@pytest.fixture
def f(task):
    """Filemon's construction of the example's driven crank."""
    return task.filemon(C0)
