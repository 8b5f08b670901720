# Type stubs of the package anisotropic_fairing, checked against the installed module by mypy's stubtest
# (the test command's python_package step). The report's types are in report.py.
from typing import Any, Callable, Literal, Optional, Sequence, Tuple, TypeVar, Union, overload

import numpy as np
import numpy.typing as npt

from .report import FairingReport as FairingReport
from .report import FairingRun as FairingRun
from .report import FairingStep as FairingStep
from .report import InitialSurface as InitialSurface
from .report import NoiseModel as NoiseModel
from .report import StepInfo as StepInfo

__all__ = ['fair', 'limit_surface', 'LimitSurface', 'FairingError', 'fair_meshio', 'fair_open3d', 'fair_vtk',
           'FairingReport', 'FairingRun', 'FairingStep', 'InitialSurface', 'NoiseModel', 'StepInfo', '__version__']

__version__: str

_Points = npt.NDArray[np.float64]
_Triangles = npt.NDArray[np.int64]

class FairingError(RuntimeError):
    """Raised when a run fails (the mesh collapsed, folded, or the solver failed); ``report`` is its report."""
    report: FairingReport

# its keyword parameters, after quiet, are the parameter table's (_core.parameter_names, in that order; the
# test test_parameter_table.py checks them and their words against it)
def fair(V: npt.ArrayLike, F: npt.ArrayLike, *, attributes: Optional[npt.ArrayLike] = None,
         vertex_is_constrained: Optional[npt.ArrayLike] = None,
         callback: Optional[Callable[[StepInfo], Optional[bool]]] = None, quiet: bool = False,
         time_step: Optional[float] = None, relative_time_step: Optional[float] = None,
         flow_order: Optional[Literal[2, 4]] = None, number_of_iterations: Optional[int] = None,
         stopping_criteria: Optional[Literal['auto', 'noise', 'paper', 'off']] = None, strength: Optional[float] = None,
         fidelity_weight: Optional[float] = None, relative_fidelity_weight: Optional[float] = None,
         relative_maximum_deviation: Optional[float] = None, absolute_maximum_deviation: Optional[float] = None,
         maximum_deviation: Optional[float] = None, attribute_maximum_deviation: Optional[float] = None,
         tensor: Optional[Literal['isotropic', 'anisotropic', 'uniform']] = None,
         lambda_: Optional[float] = None, epsilon: Optional[float] = None,
         tangential_motion: Optional[Literal['remove', 'keep']] = None,
         finite_element: Optional[Literal['loop', 'linear']] = None,
         output_positions: Optional[Literal['limit', 'control']] = None,
         attribute_mode: Optional[Literal['separate', 'coupled', 'attributes', 'geometry']] = None,
         attribute_weight: Optional[float] = None, boundary_handling: Optional[Literal['curve', 'vertices']] = None,
         linear_solver: Optional[Literal['auto', 'cg', 'cholesky']] = None, quadrature_degree: Optional[int] = None,
         memory_limit: Optional[float] = None) -> Tuple[_Points, Optional[npt.NDArray[np.float64]], FairingReport]: ...

class LimitSurface:
    """The Loop limit surface of a triangle mesh (see limit_surface())."""
    @property
    def positions(self) -> _Points: ...
    @property
    def normals(self) -> _Points: ...
    @property
    def area(self) -> float: ...
    def curvatures(self) -> dict[str, npt.NDArray[np.float64]]: ...
    @overload
    def resample(self, levels: int, attributes: None = None) -> Tuple[_Points, _Triangles]: ...
    @overload
    def resample(self, levels: int,
                 attributes: npt.ArrayLike) -> Tuple[_Points, _Triangles, npt.NDArray[np.float64]]: ...

def limit_surface(V: npt.ArrayLike, F: npt.ArrayLike, *, quadrature_degree: int = 8) -> LimitSurface: ...

def fair_meshio(mesh: Any, *, attributes: Union[str, Sequence[str]] = (),
                **parameters: Any) -> Tuple[Any, FairingReport]: ...
def fair_open3d(mesh: Any, *, colours: bool = True, **parameters: Any) -> Tuple[Any, FairingReport]: ...

_PolyData = TypeVar('_PolyData')   # a vtkPolyData (VTK ships no type information), e.g. a pyvista.PolyData

def fair_vtk(mesh: _PolyData, *, attributes: Union[str, Sequence[str]] = (),
             **parameters: Any) -> Tuple[_PolyData, FairingReport]: ...
