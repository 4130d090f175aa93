from typing import Any, Optional

import numpy.typing as npt

from . import Patch, Report

def assert_certified(
    patch: Patch,
    points: npt.ArrayLike,
    values: npt.ArrayLike,
    tolerance: str = ...,
    precision: Optional[str] = ...,
    cartesian: bool = ...,
    **kwargs: Any,
) -> Report: ...
