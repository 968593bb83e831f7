"""Type stubs of the native module ``ballscrew._ballscrew`` (re-exported by ``ballscrew``).

Units are in every name: speeds in rpm, loads in N, torques in N m; a screw's read-only
properties in SI (lengths in m, moduli in Pa); ``contact`` and ``Screw.replace`` in the command
line's and the spec file's units (mm, GPa, ...).

Number arguments take real numbers: Python ints and floats, numpy integer and floating scalars
and arrays (any width), lists of those, object arrays of real numbers. Anything else raises
ValueError naming the argument (and the index of an element): bools, complex numbers, datetimes
and timedeltas (numpy's and Python's), texts, None where a number is required, ints too large for
a float, and numpy masked arrays (numpy would ignore the mask: pass ``.filled(value)`` or drop the
masked points). Long calls (``Screw.torque`` on arrays, ``Screw.sweep``, ``Screw.band``,
``Screw.sensitivity``, ``Evaluator.series``, ``Reversal.series``, ``predict``, ``diagnose``) end on Ctrl-C within a fraction of a second
(KeyboardInterrupt).

Files that cannot be read raise Python's own ``OSError`` subclasses (``FileNotFoundError``,
``IsADirectoryError``, ``PermissionError``) with the ``filename``. Batches and sweeps
(``Screw.torque``, ``Screw.sweep``, ``Evaluator.series``, ``predict``) take ``errors="raise"``
(the default: the first point the model cannot evaluate raises) or ``errors="nan"`` (each such
point gives NaN, the others are computed, and one ``EvaluationWarning`` says how many and why the
first failed); bad arguments raise either way.

Calls that give torques at the caller's speeds (``Screw.torque``, ``Screw.sweep``,
``Screw.summary``, ``Screw.inspect``, ``Evaluator.torque``, ``Evaluator.series``, ``predict``) issue one
``QuasiStaticWarning`` when at any of their points the balls' inertia, which the quasi-static
model leaves out, is not small (the command line's warning, the same text).
"""

import os
from typing import Any, Literal, Optional, Union, overload

import numpy as np
import numpy.typing as npt

__all__ = [
    "ConvergenceError",
    "EvaluationWarning",
    "Evaluator",
    "QuasiStaticWarning",
    "StateWarning",
    "Reversal",
    "Screw",
    "contact",
    "diagnose",
    "dkfzd4012_torque_nm",
    "predict",
]

__version__: str
"""The package's version (the Rust crate's, the wheel's), e.g. ``"0.1.0"``."""

_Scalar = Union[float, int, np.floating, np.integer]
_Array = npt.ArrayLike
_Errors = Literal["raise", "nan"]

class ConvergenceError(ValueError):
    """The ball balance did not converge at an operating point (the inputs have no
    quasi-static state the model can find, e.g. balls that skid), or the ball train of a
    circuit of several loaded turns has no steady state found there."""

class EvaluationWarning(RuntimeWarning):
    """Points of a batch or sweep run with ``errors="nan"`` that the model could not evaluate and
    that came out NaN (one warning per call)."""

    count: int
    """How many points came out NaN."""
    total: int
    """Of how many points."""
    first_index: int
    """The first one's flat index (C order)."""
    first_error: str
    """Why the first one failed (the error ``errors="raise"`` would have raised, and the point)."""

class QuasiStaticWarning(UserWarning):
    """Operating points of a call where the balls' inertia, which the quasi-static model leaves
    out (their centrifugal force, their gyroscopic moment), is more than a quarter of what the
    contacts carry: the torque there is an extrapolation (DKFZD4012 at 500 N from about 4650 rpm).
    One warning per call, naming the worst point, the command line's text."""

    count: int
    """How many points are beyond the quasi-static model."""
    total: int
    """Of how many points."""
    speed_rpm: float
    """The worst point's speed, rpm."""
    preload_n: float
    """Its preload, N."""
    axial_load_n: float
    """Its axial load, N."""

class StateWarning(RuntimeWarning):
    """Audited points of an ``Evaluator`` call (or turning steps of a ``Reversal`` call) whose warm
    torque departed from the canonical state (the model's cold solve, what ``Screw.torque``
    gives) by more than the audit's tolerance: the warm solve follows its history and sits on
    another steady state of the balls there (one warning per call; ``audit`` keeps the counts).
    For a ``Reversal`` the torque compared is the steady torque its state settles on at the
    step's speed."""

    count: int
    """How many audited points (steps) of this call departed."""
    first_index: int
    """The first one's flat index (C order) among the call's points (steps)."""
    speed_rpm: float
    """Its speed, rpm."""
    preload_n: float
    """Its preload, N."""
    axial_load_n: float
    """Its axial load, N."""
    torque_nm: float
    """The evaluator's torque there (a ``Reversal``'s steady torque at the step's speed), N m."""
    canonical_torque_nm: float
    """The canonical torque there (NaN where the cold solve fails), N m."""
    relative_departure: float
    """The difference relative to the canonical drag torque."""

class Screw:
    """A ball screw: a validated spec and its model.

    Make one with ``Screw.dkfzd4012()``, ``Screw.from_toml(path)`` or ``Screw.from_toml_str(text)``.
    Invalid specs and inputs raise ValueError with the field, the value and the valid range;
    anything but real numbers (bools, complex numbers, datetimes, texts, None, masked arrays)
    raises ValueError naming the argument.
    """

    @staticmethod
    def dkfzd4012() -> Screw:
        """The DKFZD4012 screw of Table 1 of Xu et al. (2015): the command line's built-in spec."""
    @staticmethod
    def from_toml(path: Union[str, os.PathLike[str]]) -> Screw:
        """A screw from a TOML spec file (units in the key names). FileNotFoundError,
        IsADirectoryError or PermissionError when it cannot be read; ValueError naming the file
        and the key for invalid TOML and values."""
    @staticmethod
    def from_toml_str(text: str, origin: str = "<string>") -> Screw:
        """A screw from the text of a TOML spec; ``origin`` names it in error messages."""
    def to_toml(self) -> str:
        """The spec as TOML text (units in the key names)."""
    def replace(self, changes: Optional[dict[str, Any]] = None, /, **kwargs: Any) -> Screw:
        """A new screw with spec values changed, as editing the TOML text and loading it would
        give it: ``screw.replace(friction_coefficient=0.05)`` or
        ``screw.replace({"friction.coefficient": 0.05})``. Names are the spec file's keys, values
        in their units (mm, deg, GPa, rpm, ...): the dotted key, the dotted key with underscores
        (``friction_coefficient``, ``geometry_lead_mm``), or the key alone where no other table has
        it (``lead_mm``, ``preload_n``). A dotted key may add a key the text leaves out; ``None``
        removes an optional key. Unknown names raise ValueError with the closest known names;
        values are checked as loading the TOML checks them (the same messages). Values not
        changed keep their exact SI values."""
    @overload
    def torque(
        self,
        preload_n: _Scalar,
        speed_rpm: Optional[_Scalar] = None,
        axial_load_n: Optional[_Scalar] = None,
        *,
        errors: _Errors = "raise",
        start: Literal["canonical", "warm"] = "canonical",
    ) -> float:
        """Drive (drag) torque in N m; floats give a float: the point's canonical state (the
        model's cold solve), ``ballscrew torque``'s number to the bit, whatever was asked before."""
    @overload
    def torque(
        self,
        preload_n: _Array,
        speed_rpm: Optional[_Array] = None,
        axial_load_n: Optional[_Array] = None,
        *,
        errors: _Errors = "raise",
        start: Literal["canonical", "warm"] = "canonical",
    ) -> Union[float, npt.NDArray[np.float64]]:
        """Drive (drag) torque in N m; arrays broadcast (at most 1e8 points) and give an array of their shape.

        ``start="canonical"`` (the default): each point is its canonical state (the model's cold
        solve over the machine's cores), the same bits as the scalar call, on any number of
        threads and whatever the other points. ``start="warm"``: the control-loop evaluator band
        by band of speed, tens of times faster on large batches, within 1e-8 of the canonical
        torque except where a ball has two steady states.

        ``errors="nan"``: a point the model cannot evaluate (e.g. beyond the static load capacity,
        or without a quasi-static state) gives NaN and the others are computed
        (``EvaluationWarning``). Ctrl-C stops the batch within a fraction of a second
        (KeyboardInterrupt)."""
    def summary(
        self,
        preload_n: Optional[_Scalar] = None,
        speed_rpm: Optional[_Scalar] = None,
        axial_load_n: Optional[_Scalar] = None,
    ) -> dict[str, Union[float, int]]:
        """Everything ``ballscrew torque`` reports for one operating point (its JSON keys, in its
        order): ``speed_rpm``, ``preload_n``, ``axial_load_n``, ``torque_nm`` and its parts
        ``drag_torque_nm`` (friction) and ``load_torque_nm`` (F_a L / (2 pi)), ``torque_energy_nm``,
        ``torque_moment_nm``, ``torque_eq27_nm``, ``dissipation_torque_nm`` and its shares by
        mechanism ``creep_torque_nm``, ``rolling_resistance_torque_nm``, ``hysteresis_torque_nm``,
        ``ball_ball_torque_nm``, ``return_torque_nm``; ``seal_torque_nm``, ``catalog_nm``,
        ``catalog_low_nm``,
        ``catalog_high_nm``, ``ratio`` (drag torque over the catalog's), ``iterations``,
        ``max_residual``; ``forward_efficiency``, ``backdrive_efficiency`` (0 when self-locking)
        and ``backdrive_torque_nm`` under an axial load, NaN without one or at standstill."""
    @overload
    def sweep(
        self,
        preload_n: Optional[_Array] = None,
        speed_rpm: Optional[_Array] = None,
        axial_load_n: Optional[_Array] = None,
        *,
        oil_temperature_c: Optional[_Array] = None,
        frame: Literal[False],
        errors: _Errors = "raise",
        band: Union[bool, tuple[float, float], None] = None,
        samples: Optional[int] = None,
        seed: Optional[int] = None,
    ) -> dict[str, npt.NDArray[Any]]:
        """The sweep as a dict of numpy arrays (``ballscrew sweep --format csv`` columns) over the
        one quantity given as a 1-d array: ``preload_n`` (the default, 500 to 3000 N by 100 N),
        ``speed_rpm`` (``ballscrew sweep --speed-rpm A..B``), ``axial_load_n``
        (``--axial-load-n A..B``) or ``oil_temperature_c`` at the contacts
        (``--oil-temperature-c A..B``; lubricated model only); the others one number each (default
        the spec's). The first column names the swept quantity, the operating point held (``preload_n``, ``speed_rpm``,
        ``axial_load_n`` and, lubricated, ``oil_temperature_c``, less the swept one, so sweeps
        stack), then ``torque_nm``, ``drag_torque_nm``, ``load_torque_nm``,
        ``torque_energy_nm``, ``torque_moment_nm``, ``torque_eq27_nm``, ``catalog_nm``,
        ``catalog_low_nm``, ``catalog_high_nm``, ``ratio`` (of the drag torque), ``iterations``,
        ``max_residual``, ``forward_efficiency``, ``backdrive_efficiency``, ``backdrive_torque_nm``
        (NaN without an axial load). With ``errors="nan"`` a point the model cannot evaluate gives
        a row of NaN but its operating point (``iterations`` then float), the others are computed
        (``EvaluationWarning``). Ctrl-C stops it between two points.

        ``band=True`` (or a ``(low, high)`` pair of quantiles, default 0.05 and 0.95) adds the band
        of the drag torque after the other columns: ``drag_torque_low_nm``,
        ``drag_torque_median_nm``, ``drag_torque_high_nm`` (N m; each row's ``Screw.band`` to the
        bit) from ``samples`` samples (default 128) by the seed ``seed`` (default 0); NaN at rows
        that failed under ``errors="nan"``. ``samples`` or ``seed`` without ``band`` raise
        ValueError naming them."""
    @overload
    def sweep(
        self,
        preload_n: Optional[_Array] = None,
        speed_rpm: Optional[_Array] = None,
        axial_load_n: Optional[_Array] = None,
        *,
        oil_temperature_c: Optional[_Array] = None,
        frame: Optional[bool] = None,
        errors: _Errors = "raise",
        band: Union[bool, tuple[float, float], None] = None,
        samples: Optional[int] = None,
        seed: Optional[int] = None,
    ) -> Any:
        """The sweep: a pandas DataFrame when pandas is installed, else a dict of arrays."""
    @overload
    def band(
        self,
        preload_n: Optional[_Scalar] = None,
        speed_rpm: Optional[_Scalar] = None,
        axial_load_n: Optional[_Scalar] = None,
        *,
        quantiles: tuple[float, float] = (0.05, 0.95),
        samples: int = 128,
        seed: int = 0,
    ) -> dict[str, float]:
        """The band of the drag torque (N m) at one operating point that the spread of the
        spec's ``[uncertainty]`` gives (each input uniform over its half-width; defaults with
        their sources in ``docs/spec-reference.md``, 0 pins an input): ``drag_torque_nm`` (the
        nominal, ``summary``'s), ``drag_torque_low_nm``, ``drag_torque_median_nm`` and
        ``drag_torque_high_nm``, the ``quantiles`` and the median of ``samples`` (8 to 65536)
        scrambled Sobol samples by the seed ``seed`` (the same bits on every run)."""
    @overload
    def band(
        self,
        preload_n: Optional[_Array] = None,
        speed_rpm: Optional[_Array] = None,
        axial_load_n: Optional[_Array] = None,
        *,
        quantiles: tuple[float, float] = (0.05, 0.95),
        samples: int = 128,
        seed: int = 0,
    ) -> dict[str, Union[float, npt.NDArray[np.float64]]]:
        """The band at each point of arrays (broadcast as in ``torque``): numpy arrays of the
        broadcast shape. A point's band does not depend on the other points. ValueError for a
        bad quantile pair, sample size or seed, or a half-width whose spread leaves its input's
        range (naming ``uncertainty.<key>``); ``ConvergenceError`` for a sample the model cannot
        evaluate; MemoryError for a band too large. Ctrl-C stops it (KeyboardInterrupt)."""
    @overload
    def sensitivity(
        self,
        preload_n: Optional[_Scalar] = None,
        speed_rpm: Optional[_Scalar] = None,
        axial_load_n: Optional[_Scalar] = None,
        *,
        samples: int = 128,
        seed: int = 0,
        frame: Literal[False],
    ) -> dict[str, Union[list[str], npt.NDArray[np.float64]]]:
        """What drives the band at one operating point: one row per active uncertain input,
        largest swing first, as a dict of columns (a ``dict`` subclass): ``input``, ``key``
        (``uncertainty.<key>``), ``half_width``, ``half_width_unit`` (lists of texts for the
        names), ``low_end_nm`` and ``high_end_nm`` (the drag torque with the input at each end of
        its spread, the others nominal), ``swing_nm``, ``first_order`` and ``total`` (Sobol
        indices). Its ``attrs`` holds ``drag_torque_nm`` (the nominal drag torque, N m) and
        ``variance_nm2`` (the drag torque's variance over the samples, N^2 m^2)."""
    @overload
    def sensitivity(
        self,
        preload_n: Optional[_Scalar] = None,
        speed_rpm: Optional[_Scalar] = None,
        axial_load_n: Optional[_Scalar] = None,
        *,
        samples: int = 128,
        seed: int = 0,
        frame: Optional[bool] = None,
    ) -> Any:
        """What drives the band: a pandas DataFrame when pandas is installed (``attrs``:
        ``drag_torque_nm``, ``variance_nm2``), else the dict of columns."""
    def with_oil_temperature(self, oil_temperature_c: _Scalar) -> Screw:
        """The same screw with the oil at ``oil_temperature_c`` (degrees C) at the contacts (the
        spec's ``lubricant.temperature_c``). ValueError naming ``oil_temperature_c`` under the dry
        model (no oil) and outside [-30, 200] degrees C."""
    def inspect(
        self,
        preload_n: Optional[_Scalar] = None,
        speed_rpm: Optional[_Scalar] = None,
        axial_load_n: Optional[_Scalar] = None,
    ) -> list[dict[str, Union[float, int, str]]]:
        """The per-contact breakdown (``ballscrew inspect --format csv`` rows) as a list of dicts:
        the ball's columns (``nut``, ``circle``, ..., ``omega_b_per_screw``), then the contact's
        (``contact``, ``normal_load_n``, ..., ``friction_bound_n``, ``friction_coefficient``,
        ``film_central_um``, ``film_minimum_um``, ``lambda``, ``rolling_resistance_ehl_n``,
        ``rolling_resistance_hysteresis_n``, ``dissipation_per_ball_nm``, ``torque_share_nm``,
        ``creep_torque_share_nm``, ``rolling_torque_share_nm``, ``hysteresis_torque_share_nm``)."""
    @property
    def origin(self) -> str:
        """Where the spec came from: a file name, ``<string>`` or the built-in spec."""
    @property
    def pitch_diameter_m(self) -> float:
        """Pitch diameter d_m (ball-centre helix diameter), m."""
    @property
    def lead_m(self) -> float:
        """Lead L (axial advance per screw revolution), m."""
    @property
    def ball_diameter_m(self) -> float:
        """Ball diameter D_w, m."""
    @property
    def conformity_screw(self) -> float:
        """Conformity of the screw groove f_s (groove radius / ball diameter)."""
    @property
    def conformity_nut(self) -> float:
        """Conformity of the nut groove f_N (groove radius / ball diameter)."""
    @property
    def contact_angle_deg(self) -> float:
        """Nominal contact angle beta, degrees."""
    @property
    def helix_angle_deg(self) -> float:
        """Helix (lead) angle alpha = atan(L / (pi d_m)), degrees."""
    @property
    def nuts(self) -> int:
        """Number of nuts: 2 for a double nut, 1 for every single-nut arrangement."""
    @property
    def preload_arrangement(self) -> str:
        """How the nut is preloaded (`geometry.preload`): "double-nut", "offset-lead",
        "oversize-ball" (four-point contact) or "none"."""
    @property
    def circles_per_nut(self) -> int:
        """Load-carrying circles (turns) per nut."""
    @property
    def balls_per_circle(self) -> int:
        """Balls per circle."""
    @property
    def youngs_modulus_pa(self) -> float:
        """Young's modulus E of balls and raceways, Pa."""
    @property
    def poisson_ratio(self) -> float:
        """Poisson's ratio nu."""
    @property
    def friction_coefficient(self) -> float:
        """Coulomb friction coefficient f of every contact under ``lubrication == "dry"`` (under
        ``"ehl"`` each raceway contact's comes from its film)."""
    @property
    def creep_reduction(self) -> float:
        """Factor (0, 1] on Kalker's creep coefficients (1: dry contact; below 1: lubricated)."""
    @property
    def seal_torque_per_nut_nm(self) -> float:
        """Drag torque of each nut's seals, N m (``friction.seal_torque_per_nut_nm``)."""
    @property
    def ball_ball_load_n(self) -> Optional[float]:
        """Normal load between adjacent balls Q_m, N, where the spec sets it; ``None``: the loads
        follow from the ball train (``[circulation]``)."""
    @property
    def standstill_speed_rpm(self) -> float:
        """Standstill speed, rpm: below it the creep forces fade to zero at standstill."""
    @property
    def default_speed_rpm(self) -> float:
        """The spec's operating speed (the default of ``speed_rpm``), rpm."""
    @property
    def default_preload_n(self) -> float:
        """The spec's preload (the default of ``preload_n`` in ``summary`` and ``inspect``), N."""
    @property
    def default_axial_load_n(self) -> float:
        """The spec's external axial load (the default of ``axial_load_n``), N."""
    @property
    def load_distribution(self) -> Literal["geometric", "paper-literal", "uniform"]:
        """Load sharing over circles."""
    @property
    def lubrication(self) -> Literal["ehl", "dry"]:
        """Whether the raceway contacts are lubricated: "ehl" (the default) or "dry"."""
    @property
    def lubricant(self) -> dict[str, float]:
        """The spec's ``[lubricant]`` table, keyed and in the units of a spec file
        (``viscosity_40c_mm2_s``, ``viscosity_100c_mm2_s``, ..., ``temperature_c``, ...)."""
    @property
    def oil_temperature_c(self) -> Optional[float]:
        """The oil temperature at the contacts (``lubricant.temperature_c``), degrees C; None
        under ``lubrication == "dry"``."""
    @property
    def creep_coefficients(self) -> Literal["kalker-table", "paper-fit"]:
        """Source of the creep coefficients."""
    @property
    def torque_route(self) -> Literal["energy", "paper-eq27"]:
        """The torque reported as the torque."""
    @property
    def heathcote(self) -> bool:
        """Whether Heathcote slip is included."""
    @property
    def spin_moment(self) -> Literal["combined", "separate"]:
        """Spin moment at the raceway contacts."""
    @property
    def contact_theory(self) -> Literal["linear-saturated", "fastsim"]:
        """Contact theory of the raceway contacts."""
    @property
    def fastsim_grid(self) -> int:
        """FASTSIM elements per axis of the contact ellipse."""

class Evaluator:
    """The model's drive torque for a control loop or a drive simulation: the core's real-time
    evaluator in f64 (within 1e-8 of ``Screw.torque``, but where a ball has two steady states) or f32 (within 1e-4), each call
    warm-started from the previous calls on the same evaluator.

    Speeds are in rpm, loads in N, torques in N m. Specs with ``model.contact_theory = "fastsim"``
    or ``geometry.preload = "oversize-ball"``, which the evaluator does not take, run on the
    model's own solve in f64 (``solver == "model"``: the torques of ``Screw.torque`` at the
    model's cost, about 0.2 ms a warm point of a four-point screw); in f32 they are refused
    (ValueError naming the key). f32's 1e-4 is relative to the drag torque where the axial
    load's torque cancels it.
    """

    def __init__(self, screw: Screw, precision: Literal["f64", "f32"] = "f64", *, audit_every: int = 1000) -> None:
        """An evaluator of ``screw``'s model (a few milliseconds to build); ValueError for another
        precision. Its first point and every ``audit_every``-th point after it are also solved
        cold and compared with the warm answer (``audit``; 0 audits nothing): a call with a
        point that departs from the canonical state raises a ``StateWarning``."""
    def torque(
        self, preload_n: _Scalar, speed_rpm: Optional[_Scalar] = None, axial_load_n: Optional[_Scalar] = None
    ) -> float:
        """Drive torque in N m at one point (floats; ``None``: the spec's value), warm-started."""
    @overload
    def series(
        self,
        preload_n: _Scalar,
        speed_rpm: Optional[_Scalar] = None,
        axial_load_n: Optional[_Scalar] = None,
        *,
        errors: _Errors = "raise",
    ) -> float:
        """One point: a float, as from ``Screw.torque``."""
    @overload
    def series(
        self,
        preload_n: _Array,
        speed_rpm: Optional[_Array] = None,
        axial_load_n: Optional[_Array] = None,
        *,
        errors: _Errors = "raise",
    ) -> Union[float, npt.NDArray[np.float64]]:
        """Drive torque in N m over broadcast arrays evaluated in C order as a time series, each
        point warm-started from the one before; an array of the broadcast shape. With
        ``errors="nan"`` a point without solution gives NaN and the series goes on
        (``EvaluationWarning``). Ctrl-C stops it between two points (KeyboardInterrupt), the
        evaluator warm from the last one evaluated."""
    def reset(self) -> None:
        """Forgets the warm state (the next point starts cold: from the evaluator's table, or by the model's continuation); the audit's counts start again."""
    @property
    def audit(self) -> dict[str, Any]:
        """What the audit found since the evaluator was built or reset: ``audit_every``,
        ``tolerance`` (relative to the drag torque: 1e-6 in f64, 5e-4 in f32), ``calls``,
        ``audited``, ``departed``, ``largest_departure`` and ``first_departure`` (None, or a dict
        of ``preload_n``, ``speed_rpm``, ``axial_load_n``, ``torque_nm``,
        ``canonical_torque_nm``, ``relative_departure``)."""
    @property
    def precision(self) -> Literal["f64", "f32"]:
        """The float type the evaluator computes in."""
    @property
    def tolerance(self) -> float:
        """Tolerance of the balance's solve on the residual (dimensionless): 1e-9 in f64, 1e-5 in f32; 1e-12 on the model's solve."""
    @property
    def solver(self) -> Literal["evaluator", "model"]:
        """What evaluates the torques: the control-loop evaluator, or the model's own solve (f64) for a spec it does not take."""
    def __reduce__(self) -> tuple[Any, ...]:
        """Pickling and ``copy``: the screw, the precision and ``audit_every``; the copy starts cold (as after ``reset``)."""

class Reversal:
    """The drive torque through reversals, for a servo simulation that steps the screw's
    rotation: a friction state per circle of balls that re-forms over the small rotation after a
    reversal (presliding, Dahl's law), whose steady state at a constant speed is the static
    model's torque (``Screw.torque``, within 1e-8 in f64 and 1e-4 in f32).

    Built at one preload and axial load; starts relaxed (no friction stored). Rotations are in
    rad (the screw's angle), time steps in s, speeds in rpm, loads in N, torques in N m. Specs
    with extension terms or ``model.contact_theory = "fastsim"`` are refused (ValueError).
    """

    def __init__(
        self,
        screw: Screw,
        preload_n: Optional[_Scalar] = None,
        axial_load_n: Optional[_Scalar] = None,
        precision: Literal["f64", "f32"] = "f64",
        *,
        audit_every: int = 1000,
    ) -> None:
        """The reversal model of ``screw`` at ``preload_n`` and ``axial_load_n`` (N; ``None``: the
        spec's operating value) in ``precision``, relaxed (a fraction of a second to build). Its
        first turning step and every ``audit_every``-th after it compare the steady torque the
        state settles on at the step's speed with the canonical one (``audit``; 0 audits
        nothing): a step that departs raises a ``StateWarning``."""
    def step(self, rotation_rad: _Scalar, dt_s: _Scalar) -> float:
        """Turns the screw by ``rotation_rad`` (rad, signed) over ``dt_s`` (s, > 0); the drive
        torque in N m at the step's end (the circles' friction, the axial load's torque, the
        seals). The step's speed sets the steady friction; a zero rotation keeps the friction."""
    def series(self, rotation_rad: _Array, dt_s: _Array) -> npt.NDArray[np.float64]:
        """Drive torque in N m after each step of broadcast arrays of rotations (rad) and time
        steps (s) taken in C order; equal bit for bit to ``step`` in that order. Every step is
        checked first (ValueError with the index); a failing step raises naming its index, the
        state keeping the steps before. Ctrl-C stops it between two steps (KeyboardInterrupt)."""
    def reset(self, speed_rpm: Optional[_Scalar] = None) -> None:
        """``None``: the relaxed state (no friction stored); a nonzero speed in rpm: the steady
        state of the screw running at it."""
    def __reduce__(self) -> tuple[Any, ...]:
        """Pickling and ``copy``: the screw, the loads, the precision, ``audit_every`` and the state
        (the friction it holds and the evaluator's warm memory), so that the copy continues bit
        for bit as the original; the audit's counts start again."""
    def __setstate__(self, state: tuple[list[float], list[float]]) -> None:
        """Sets the friction of a pickle's state; ValueError unless it fits the model."""
    @property
    def audit(self) -> dict[str, Any]:
        """What the audit found since the model was built or reset, as ``Evaluator.audit``
        (``calls``: the steps that turn)."""
    @property
    def precision(self) -> Literal["f64", "f32"]:
        """The float type the model computes in."""
    @property
    def preload_n(self) -> float:
        """The preload the model was built at, N."""
    @property
    def axial_load_n(self) -> float:
        """The external axial load the model was built at, N."""
    @property
    def stiffness_nm_per_rad(self) -> float:
        """Dahl's stiffness summed over the circles and mechanisms, N m/rad: the initial slope of
        the friction torque against the screw's angle turning from the relaxed state (either way);
        after a reversal from steady running the slope starts near twice it."""
    @property
    def friction_nm(self) -> float:
        """The friction torque the state holds now, N m (without the axial load's torque and the
        seals; 0 when relaxed)."""

def dkfzd4012_torque_nm(preload_n: _Scalar, speed_rpm: Optional[_Scalar] = 100.0) -> float:
    """Drag torque of the built-in DKFZD4012 screw, no axial load, N m (cold start);
    ``speed_rpm=None`` is 100 rpm."""

def contact(
    semi_axis_rolling_mm: _Scalar,
    semi_axis_lateral_mm: _Scalar,
    normal_load_n: _Scalar,
    *,
    xi: _Scalar = 0.0,
    eta: _Scalar = 0.0,
    phi_per_mm: _Scalar = 0.0,
    heathcote_per_mm2: _Scalar = 0.0,
    friction: _Scalar = 0.03,
    youngs_modulus_gpa: _Scalar = 210.0,
    poisson_ratio: _Scalar = 0.3,
    grid: int = 40,
    bound: Literal["parabolic", "elliptical"] = "parabolic",
) -> dict[str, Any]:
    """One rolling contact by FASTSIM over its Hertz ellipse, in the units, names and ranges of
    ``ballscrew contact``: semi-axes in mm ([1e-4, 100]), load in N ([1e-6, 1e7]), ``xi``,
    ``eta`` dimensionless, ``phi_per_mm`` in 1/mm, ``heathcote_per_mm2`` in 1/mm^2 (each
    |value| <= 1000), ``friction`` in [1e-4, 1], ``youngs_modulus_gpa`` in [1, 1000],
    ``poisson_ratio`` in [0, 0.5], ``grid`` in [1, 400]; anything else raises ValueError in the
    command line's words. (Before, this function took metres and Pa and allowed a grid of 1000.)

    Returns the forces ``force_e_n``, ``force_f_n``, ``spin_moment_nm``,
    ``dissipation_per_speed_n``, ``adhesion_elements``, ``slip_elements``, ``adhesion_share``,
    and the traction field as (grid x grid) numpy arrays: ``x_mm``, ``y_mm``, ``area_mm2``,
    ``traction_x_mpa``, ``traction_y_mpa``, ``bound_mpa`` (MPa = N/mm^2: traction times area
    sums to N), ``slip_x``, ``slip_y``, ``sliding``."""

_Data = Union[str, os.PathLike[str], dict[str, Any], Any]
"""A CSV path, a dict of columns, a pandas DataFrame or a numpy structured array."""
_Spec = Union[Screw, str, os.PathLike[str], None]

def diagnose(
    data: _Data,
    spec: _Spec = None,
    columns: Optional[dict[str, str]] = None,
    delimiter: Optional[str] = None,
) -> dict[str, Any]:
    """Diagnose measured drag torques (a CSV path, a dict of columns, a pandas DataFrame or a
    numpy structured array, ``torque_nm`` required) against a spec (a ``Screw``, a TOML path, or
    the built-in DKFZD4012): the report of ``ballscrew diagnose --report`` (its keys and values)
    as dicts, lists of records, floats, ints, texts and None, with its tables of numbers as one
    1-d numpy array per column (float64; int64 for counts and harmonics): each residual's
    ``bins`` (``from``, ``to``, ``mean_residual_nm``, ``rows``) and the ``position_periodogram``
    (``harmonic``, ``baseline_amplitude_nm``, ``extended_amplitude_nm``). Beside the report's
    keys, ``row_torques``: per data row, in the data's order, ``measured_torque_nm``,
    ``spec_model_torque_nm``, ``calibrated_torque_nm`` and ``extended_torque_nm``, a dict of
    float64 arrays, or for a pandas DataFrame a DataFrame on the frame's index. Columns are 1-d sequences of real numbers, validated as a CSV's (the same names and errors).
    ``columns`` maps a column name to the data's own name, e.g. ``{"time_h": "hours"}``.
    ``delimiter`` of a CSV file: ``","``, ``";"`` or ``"\t"`` (or ``"comma"``, ``"semicolon"``,
    ``"tab"``); found from the header line when not given. A file that cannot be read raises
    FileNotFoundError, IsADirectoryError or PermissionError. Ctrl-C raises KeyboardInterrupt
    within a fraction of a second, the diagnosis stopped (nothing keeps computing after the
    call)."""

def predict(
    data: _Data,
    spec: _Spec = None,
    columns: Optional[dict[str, str]] = None,
    delimiter: Optional[str] = None,
    *,
    errors: _Errors = "raise",
) -> Any:
    """The model's drive torque, N m, for every row of ``data`` (extension terms of the spec
    included, with each row's position, temperature and running time); ``data``, ``columns`` and
    ``delimiter`` as for ``diagnose``. Returns a float64 numpy array, or for a pandas DataFrame a
    ``Series`` named ``torque_nm`` on the frame's index. A row the model cannot evaluate raises
    ValueError naming it, or with ``errors="nan"`` gives NaN (``EvaluationWarning``). Columns it
    does not use give a ``UserWarning`` naming them, as the command line warns, and so does a
    ``temperature_c`` column under the lubricated model (the oil at the contacts stays at the
    spec's ``lubricant.temperature_c`` on every row; the column reaches only the
    ``thermal_viscosity`` term). Rows where the balls' inertia is not small give one
    ``QuasiStaticWarning``. Ctrl-C stops it between two rows."""
