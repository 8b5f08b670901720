"""The report of a run as a typed dictionary: the keys and value types of the program's JSON report
(``anisotropic_fairing --report``), which :func:`anisotropic_fairing.fair` returns as a ``dict``.

A key whose value the run does not know (a setting not given, a number that is not finite) holds ``None``.
The manual's page on the program lists what each key means.
"""
from typing import List, Optional, TypedDict

__all__ = ['FairingReport', 'FairingRun', 'FairingStep', 'InitialSurface', 'StepInfo']


class InitialSurface(TypedDict):
    """The input's limit surface (``report['initial']``)."""
    area: Optional[float]
    energy: Optional[float]
    H_integral: Optional[float]


class NoiseModel(TypedDict):
    """The noise model read from the mesh with automatic parameters (``report['noise_model']``)."""
    tangential_noise_level: Optional[float]
    noise_level_spread: Optional[float]
    tangential_noise_level_spread: Optional[float]
    impulse_share: Optional[float]
    impulse_deviation: Optional[float]
    lattice_step: List[Optional[float]]


class FairingStep(TypedDict):
    """One accepted time step (``report['steps'][k]``)."""
    step: int
    time: Optional[float]
    solver_iterations: int
    residual: Optional[float]
    area: Optional[float]
    energy: Optional[float]
    H_integral: Optional[float]
    max_displacement: Optional[float]
    step_displacement: Optional[float]
    assemble_seconds: Optional[float]
    solve_seconds: Optional[float]
    direct_solve: bool
    time_step: Optional[float]
    noise_displacement: Optional[float]


class FairingRun(TypedDict):
    """One run the call made (``report['runs'][k]``, in order): the default run's candidate flows, a flow's run on
    the probed input, the kept flow's run to ``strength``; one entry for any other call. ``estimate`` is the risk
    estimate the comparison gave its result (``None``: none), ``kept`` whether its result was written;
    ``stop_reason`` ``'dropped'``: the comparison ended the run, its estimate above another's."""
    name: str
    steps: int
    rejected_steps: int
    seconds: Optional[float]
    status: str
    stop_reason: str
    estimate: Optional[float]
    kept: bool


class StepInfo(TypedDict):
    """What a ``callback`` of :func:`anisotropic_fairing.fair` receives after each step; ``step`` counts the
    steps of its run, ``run`` (1, 2, ...) says which of at most ``runs`` (the default run compares several
    flows), ``run_name`` what it is ('' when the call makes one run)."""
    step: int
    time: float
    time_step: float
    area: float
    energy: float
    H_integral: float
    max_displacement: float
    solver_iterations: int
    run: int
    runs: int
    run_name: str


# The functional form: one key, ``lambda``, is a Python keyword.
FairingReport = TypedDict('FairingReport', {
    'status': str,
    'message': str,
    'input': Optional[str],
    'output': Optional[str],
    'vertices': Optional[int],
    'faces': Optional[int],
    'input_changes': List[str],
    'split_vertices': Optional[int],
    'triangulated_faces': Optional[int],
    'element': str,
    'output_positions': str,
    'tensor': str,
    'lambda': Optional[float],
    'lambda_model_units': Optional[float],
    'epsilon': Optional[float],
    'tangential_motion': str,
    'solver': Optional[str],
    'requested_solver': str,
    'stop': str,
    'strength': Optional[float],
    'max_steps': int,
    'quadrature_degree': int,
    'time_step': Optional[float],
    'order': int,
    'relative_time_step': Optional[float],
    'scale': Optional[float],
    'fidelity_weight': Optional[float],
    'relative_fidelity_weight': Optional[float],
    'mean_edge_length': Optional[float],
    'normals': str,
    'curvature': bool,
    'hold': Optional[str],
    'held_vertices': int,
    'resample': Optional[int],
    'resampled_vertices': Optional[int],
    'resampled_faces': Optional[int],
    'snapshot': Optional[str],
    'mode': str,
    'attributes': List[str],
    'attribute_dimension': Optional[int],
    'attribute_weight': Optional[float],
    'boundary_handling': str,
    'boundary_vertices': Optional[int],
    'boundary_held_vertices': Optional[int],
    'boundary_loops': Optional[int],
    'isolated_vertices': Optional[int],
    'constrained_vertices': Optional[int],
    'stop_reason': Optional[str],
    'automatic_parameters': bool,
    'choices': Optional[str],
    'noise_level': Optional[float],
    'noise_deviation': Optional[float],
    'noise_correlation': Optional[float],
    'noise_correlation_factor': Optional[float],
    'noise_displacement': Optional[float],
    'removed_spikes': Optional[int],
    'noise_model': Optional[NoiseModel],
    'limit_weight': Optional[float],
    'components': Optional[int],
    'rejected_steps': Optional[int],
    'absolute_maximum_deviation': Optional[float],
    'maximum_deviation': Optional[float],   # deprecated: absolute_maximum_deviation (model units)
    'relative_maximum_deviation': Optional[float],
    'largest_deviation': Optional[float],
    'attribute_maximum_deviation': Optional[float],
    'largest_attribute_deviation': Optional[float],
    'bound_fidelity_weight': Optional[float],
    'bound_held_vertices': Optional[int],
    'bound_uniform_weight': Optional[float],
    'bound_retaken_steps': Optional[int],
    'clamped_vertices': Optional[int],
    'initial': Optional[InitialSurface],
    'steps': List[FairingStep],
    'runs': List[FairingRun],
    'read_seconds': Optional[float],
    'input_seconds': Optional[float],
    'setup_seconds': Optional[float],
    'write_back_seconds': Optional[float],
    'total_seconds': Optional[float],
    'write_seconds': Optional[float],
    'wall_seconds': Optional[float],
    'memory_in_use_mb': Optional[float],
    'predicted_memory_mb': Optional[float],
    'predicted_peak_memory_mb': Optional[float],
    'available_memory_mb': Optional[float],
    'memory_limited_by': Optional[str],
    'peak_memory_mb': Optional[float],
})
FairingReport.__doc__ = """The report of a run: the program's JSON report (``anisotropic_fairing --report``) as a
dict."""
