"""Type stubs of the public API of tribez."""

import os
from fractions import Fraction
from typing import Any, Callable, Literal, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

from ._errors import CertificationError as CertificationError
from ._errors import InputError as InputError
from ._errors import InternalError as InternalError
from ._errors import TribezError as TribezError

__version__: str
MAX_DEGREE: int
MAX_CONTROL_POINTS: int
MAX_SIMPLEX_DIMENSION: int
MAX_RANDOM_POINTS: int
MAX_INVERSE_ROWS: int
MAX_HUNT_BUDGET: int
MAX_HUNT_BATCH: int
MAX_HUNT_TOP: int

# A number: an int, a float (its exact value), a Fraction, or a string in tribez's syntax.
Number = Union[int, float, Fraction, str, np.integer, np.floating]
Rows = Union[npt.ArrayLike, Sequence[Sequence[Number]], Sequence[Number]]
PathLike = Union[str, "os.PathLike[str]"]
PrecisionName = Literal["f64", "f32"]
Kind = Literal["bezier", "rational", "functional", "s-patch"]

def parse_number(x: Number) -> Fraction: ...

class Patch:
    @classmethod
    def from_file(cls, path: PathLike) -> Patch: ...
    @classmethod
    def from_toml(cls, text: str, name: str = ...) -> Patch: ...
    @classmethod
    def from_json(cls, text: str, name: str = ...) -> Patch: ...
    @classmethod
    def from_nodes(
        cls,
        nodes: Union[npt.ArrayLike, Sequence[Sequence[Number]]],
        degree: Optional[int] = ...,
        weights: Optional[Union[npt.ArrayLike, Sequence[Number]]] = ...,
        simplex: int = ...,
    ) -> Patch: ...
    @property
    def degree(self) -> int: ...
    @property
    def dimension(self) -> int: ...
    @property
    def simplex(self) -> int: ...
    @property
    def kind(self) -> Kind: ...
    @property
    def name(self) -> Optional[str]: ...
    @property
    def nodes(self) -> list[list[Fraction]]: ...
    @property
    def weights(self) -> Optional[list[Fraction]]: ...
    def to_toml(self) -> str: ...
    def to_json(self) -> str: ...
    def evaluate(self, points: Rows, cartesian: bool = ...) -> list[tuple[Fraction, ...]]: ...
    def evaluate_float(
        self, points: npt.ArrayLike, precision: PrecisionName = ...
    ) -> npt.NDArray[Any]: ...

TOLERANCES: str

class Report:
    @property
    def passed(self) -> int: ...
    @property
    def failed(self) -> int: ...
    @property
    def ok(self) -> bool: ...
    @property
    def fell_back(self) -> Optional[int]: ...
    @property
    def tolerance(self) -> Optional[str]: ...
    @property
    def precision(self) -> Optional[str]: ...
    @property
    def max_ulps(self) -> Optional[float]: ...
    @property
    def worst(self) -> Optional[dict[str, Any]]: ...
    @property
    def histogram(self) -> Optional[dict[str, int]]: ...
    @property
    def rows(self) -> dict[str, npt.NDArray[Any]]: ...
    def to_json(self) -> str: ...
    def merge(self, other: Report) -> Report: ...
    def raise_if_failed(self) -> None: ...
    def failure_text(self) -> str: ...

class ClaimsReport(Report):
    @property
    def errata(self) -> int: ...
    @property
    def claims(self) -> int: ...
    @property
    def files(self) -> int: ...
    @property
    def summary(self) -> dict[str, Any]: ...
    @property
    def results(self) -> list[dict[str, Any]]: ...
    @property
    def fell_back(self) -> None: ...  # type: ignore[override]

class CertifyReport(Report):
    @property
    def results(self) -> list[dict[str, Any]]: ...
    @property
    def points(self) -> int: ...
    @property
    def seed(self) -> Optional[int]: ...
    @property
    def reproduce(self) -> Optional[str]: ...
    @property
    def fell_back(self) -> None: ...  # type: ignore[override]

class InverseReport(Report):
    @property
    def kind(self) -> Literal["locate", "ray"]: ...
    @property
    def anywhere(self) -> bool: ...
    @property
    def checked(self) -> int: ...
    @property
    def missed(self) -> int: ...
    @property
    def extra(self) -> int: ...
    @property
    def out_of_tolerance(self) -> int: ...
    @property
    def infinite(self) -> int: ...
    @property
    def not_finite(self) -> int: ...
    @property
    def failures(self) -> list[dict[str, Any]]: ...
    @property
    def fell_back(self) -> None: ...  # type: ignore[override]
    @property
    def worst(self) -> None: ...  # type: ignore[override]

def check_claims(path: PathLike) -> ClaimsReport: ...
def check_locate(
    patch: Patch,
    points: Rows,
    claimed: Sequence[Optional[Rows]],
    tolerance: str = ...,
    precision: Optional[PrecisionName] = ...,
    anywhere: bool = ...,
) -> InverseReport: ...
def check_ray(
    patch: Patch,
    rays: Rows,
    hits: Sequence[Optional[Sequence[Number]]],
    tolerance: str = ...,
    precision: Optional[PrecisionName] = ...,
) -> InverseReport: ...
def certify(
    patch: Patch,
    points: Optional[Rows] = ...,
    random: Optional[int] = ...,
    seed: Optional[int] = ...,
    precision: Literal["f64", "f32", "all"] = ...,
    algorithm: Literal["casteljau", "bernstein", "all"] = ...,
) -> CertifyReport: ...
def threads() -> int: ...
def check(
    patch: Patch,
    points: npt.ArrayLike,
    values: npt.ArrayLike,
    tolerance: str = ...,
    precision: Optional[PrecisionName] = ...,
    cartesian: bool = ...,
    *,
    algorithm: Literal["casteljau", "bernstein"] = ...,
    first_row: int = ...,
) -> Report: ...

class HuntRow:
    row: int
    input: tuple[float, ...]
    claimed: tuple[float, ...]
    exact: tuple[Fraction, ...]
    ulps: float
    passed: bool
    reason: Optional[str]
    def __init__(
        self,
        row: int,
        input: tuple[float, ...],
        claimed: tuple[float, ...],
        exact: tuple[Fraction, ...],
        ulps: float,
        passed: bool,
        reason: Optional[str],
    ) -> None: ...

class HuntReport:
    @property
    def evaluated(self) -> int: ...
    @property
    def broke(self) -> int: ...
    @property
    def ok(self) -> bool: ...
    @property
    def seed(self) -> int: ...
    @property
    def budget(self) -> int: ...
    @property
    def precision(self) -> PrecisionName: ...
    @property
    def tolerance(self) -> str: ...
    @property
    def cartesian(self) -> bool: ...
    @property
    def by_kind(self) -> dict[str, int]: ...
    @property
    def max_ulps(self) -> Optional[float]: ...
    @property
    def worst(self) -> list[HuntRow]: ...
    def text(self) -> str: ...
    def json(self) -> str: ...
    def to_claims(self, path: PathLike) -> None: ...

def hunt(
    patch: Patch,
    fn: Callable[[npt.NDArray[Any]], npt.ArrayLike],
    *,
    precision: PrecisionName = ...,
    tolerance: str = ...,
    budget: int = ...,
    seed: Optional[int] = ...,
    cartesian: bool = ...,
    batch: int = ...,
    top: int = ...,
) -> HuntReport: ...
