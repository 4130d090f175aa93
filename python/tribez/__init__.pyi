"""Type stubs of the public API of tribez."""

import os
from fractions import Fraction
from typing import Any, Literal, Optional, Sequence, Union

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
