# Type stubs of the compiled part (pybind11, anisotropic_fairing_module.cpp); the public names and their
# full signatures are in __init__.pyi.
from typing import Any, Callable, Optional, Tuple

import numpy as np
import numpy.typing as npt

from . import FairingError as FairingError
from . import LimitSurface as LimitSurface
from . import limit_surface as limit_surface
from .report import FairingReport, StepInfo

__version__: str
parameter_names: Tuple[str, ...]

def fair(V: npt.ArrayLike, F: npt.ArrayLike, *, attributes: Optional[npt.ArrayLike] = None,
         vertex_is_constrained: Optional[npt.ArrayLike] = None,
         callback: Optional[Callable[[StepInfo], Optional[bool]]] = None,
         **parameters: Any) -> Tuple[npt.NDArray[np.float64], Optional[npt.NDArray[np.float64]], FairingReport]: ...
