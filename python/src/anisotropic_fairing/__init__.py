"""Anisotropic fairing of triangle meshes and of functions on them (Bajaj & Xu 2003) with Loop-subdivision
finite elements: the Anisotropic_fairing package for numpy arrays.

    import anisotropic_fairing as af
    V2, _, report = af.fair(V, F)        # the default run: every parameter chosen from the mesh

:func:`fair` fairs a mesh given as arrays (and functions on it, as ``attributes``); :func:`limit_surface`
gives its Loop limit surface (exact positions, normals, curvatures, finer meshes); :func:`fair_meshio`,
:func:`fair_open3d` and :func:`fair_vtk` fair a ``meshio.Mesh``, an Open3D ``TriangleMesh`` and a VTK
``vtkPolyData`` (a PyVista ``PolyData`` too). The types are in the package's stubs (``__init__.pyi``); the
report is a :class:`FairingReport`.
"""
import inspect as _inspect

from . import _core
from ._core import FairingError, LimitSurface, __version__, limit_surface
from ._progress import Progress as _Progress
from .meshes import fair_meshio, fair_open3d, fair_vtk
from .report import FairingReport, FairingRun, FairingStep, InitialSurface, NoiseModel, StepInfo

__all__ = ['fair', 'limit_surface', 'LimitSurface', 'FairingError', 'fair_meshio', 'fair_open3d', 'fair_vtk',
           'FairingReport', 'FairingRun', 'FairingStep', 'InitialSurface', 'NoiseModel', 'StepInfo', '__version__']


def fair(V, F, *, attributes=None, vertex_is_constrained=None, callback=None, quiet=False, **parameters):
    """Fairs a triangle mesh and, if given, the functions on it; returns ``(V2, attributes2, report)``.

    ``V``: N x 3 positions (float64), ``F``: M x 3 vertex indices (integers) of an oriented 2-manifold mesh,
    with or without borders. ``attributes``: N x d (or N) float64 values per vertex, faired with the surface.
    ``vertex_is_constrained``: N values, non-zero holds the vertex. ``callback(step)``: called after each
    step with a :class:`StepInfo` dict; returning False ends the run, an exception it raises ends it and is
    raised again. A run that lasts more than about a second shows its progress on stderr (the steps, the
    run they belong to, the time elapsed; through ``tqdm`` if it is installed) unless ``quiet``; the result
    is the same either way. Ctrl-C raises KeyboardInterrupt at the end of the step it arrives in (or of the
    first step, during the set-up before it), leaving the inputs as they were.

    Every other parameter left at None takes its default; with none given this is the default run, every
    setting chosen from the mesh (noise estimate, tensor, time step, stop at the noise level), as the
    command-line program ``anisotropic_fairing`` does. They are the library's named parameters:
    ``time_step`` or ``relative_time_step`` (units of l^2, l the model's scale), ``flow_order`` (2 or 4),
    ``number_of_iterations``, ``stopping_criteria`` ('auto', 'noise', 'paper', 'off'), ``strength`` (the
    noise stop's target in units of the estimated noise: 2 smooths more, 0.5 less; default 1; the tensor and
    the choice of the result kept stay automatic; it needs the noise stop), ``fidelity_weight``
    or ``relative_fidelity_weight``, ``relative_maximum_deviation`` (units of l) or
    ``absolute_maximum_deviation`` (model units; ``maximum_deviation``: the relative one's deprecated
    spelling), ``attribute_maximum_deviation``, ``finite_element`` ('loop', 'linear'), ``output_positions``
    ('limit', 'control'), ``tensor`` ('isotropic', 'anisotropic', 'uniform') with, for 'anisotropic',
    ``lambda_``, ``epsilon`` and ``tangential_motion`` ('remove', 'keep'), ``linear_solver`` ('auto', 'cg',
    'cholesky'), ``boundary_handling`` ('curve', 'vertices'), ``quadrature_degree``, ``attribute_mode``
    ('separate', 'coupled', 'attributes', 'geometry'), ``attribute_weight`` and ``memory_limit`` (bytes the run
    may take; default: what the process may still take; ``math.inf``: no check; a run predicted to need more
    raises :class:`FairingError` with status 'insufficient_memory' before it starts).

    Returns the faired positions (N x 3), the faired attributes (the shape given; None without) and the
    report (:class:`FairingReport`: the keys of the program's JSON report). Raises ValueError for invalid
    input or parameters (the message names the row or the parameter), TypeError for arrays or values of the
    wrong type, :class:`FairingError` (with ``.report``) if the fairing fails. The input arrays are never
    modified; the GIL is released while the run computes.
    """
    for name in parameters:
        if name not in _core.parameter_names:
            raise TypeError("fair() got an unexpected keyword argument '%s'" % name)
    given = {name: parameters[name] for name in _core.parameter_names if parameters.get(name) is not None}
    return _run(V, F, attributes, vertex_is_constrained, callback, quiet, given)


def _with_parameters(function):
    """`function`'s signature with each of the compiled part's parameters (its parameter table) as a keyword
    of its own, default None, in place of **parameters: what help() and inspect show, and the stubs state."""
    signature = _inspect.signature(function)
    fixed = [p for p in signature.parameters.values() if p.kind != _inspect.Parameter.VAR_KEYWORD]
    named = [_inspect.Parameter(name, _inspect.Parameter.KEYWORD_ONLY, default=None) for name in _core.parameter_names]
    function.__signature__ = signature.replace(parameters=fixed + named)
    return function


fair = _with_parameters(fair)


def _run(V, F, attributes, vertex_is_constrained, callback, quiet, parameters, vertex_normals=False):
    """fair()'s run (and the adapters', which also ask for the vertex normals the program would write)."""
    if quiet:
        return _core.fair(V, F, attributes=attributes, vertex_is_constrained=vertex_is_constrained, callback=callback,
                          vertex_normals=vertex_normals, **parameters)
    with _Progress() as progress:
        def step(info):
            progress.step(info)
            return None if callback is None else callback(info)
        return _core.fair(V, F, attributes=attributes, vertex_is_constrained=vertex_is_constrained, callback=step,
                          vertex_normals=vertex_normals, **parameters)
