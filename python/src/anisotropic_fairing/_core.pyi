# Type stubs of the compiled part (pybind11, anisotropic_fairing_module.cpp); the public names and their
# full signatures are in __init__.pyi.
from typing import Any, Callable, Literal, Optional, Tuple, overload

import numpy as np
import numpy.typing as npt

from . import FairingError as FairingError
from . import LimitSurface as LimitSurface
from . import limit_surface as limit_surface
from .report import FairingReport, StepInfo

__version__: str
parameter_names: Tuple[str, ...]
parameter_words: dict[str, Tuple[str, ...]]

# with vertex_normals, the normals the program would write (None when the geometry was not faired) come fourth
@overload
def fair(V: npt.ArrayLike, F: npt.ArrayLike, *, attributes: Optional[npt.ArrayLike] = None,
         vertex_is_constrained: Optional[npt.ArrayLike] = None,
         callback: Optional[Callable[[StepInfo], Optional[bool]]] = None, vertex_normals: Literal[False] = False,
         **parameters: Any) -> Tuple[npt.NDArray[np.float64], Optional[npt.NDArray[np.float64]], FairingReport]: ...
@overload
def fair(V: npt.ArrayLike, F: npt.ArrayLike, *, attributes: Optional[npt.ArrayLike] = None,
         vertex_is_constrained: Optional[npt.ArrayLike] = None,
         callback: Optional[Callable[[StepInfo], Optional[bool]]] = None, vertex_normals: Literal[True],
         **parameters: Any) -> Tuple[npt.NDArray[np.float64], Optional[npt.NDArray[np.float64]], FairingReport,
                                     Optional[npt.NDArray[np.float64]]]: ...
