r"""Ultrasonic (pulse-echo) measurement of a bolt's elongation, and the preload it means.

An instrument times an echo from the bolt's far end before and after tightening (ASTM E1685
practice). The change in time of flight gives the change in ultrasonic length; the stress
factor turns that into the mechanical elongation (sound slows under stress, so the
ultrasonic change exceeds the mechanical one); the bolt's compliance turns the elongation
into preload. A temperature change between the two readings lengthens the ultrasonic length
by the temperature factor and is taken off first. The relations are the instrument makers'
([BoltMike], [Dakota]):

.. math::
    \Delta L_U = V\,\frac{\Delta t}{2}, \qquad
    \Delta L_U^{(T_0)} = \Delta L_U - \tau\,L_U\,\Delta T, \qquad
    \Delta L = S_F\,\Delta L_U^{(T_0)}, \qquad
    F = \frac{\Delta L}{\delta_S}

All functions take floats or numpy arrays of one shape.
"""

from __future__ import annotations

from typing import Any


def ultrasonic_length_change(time_of_flight_change: Any, sound_velocity: Any) -> Any:
    r"""Change in ultrasonic length from the change in the echo's round-trip time.

    .. math::
        \Delta L_U = V\,\frac{\Delta t}{2}

    Parameters
    ----------
    time_of_flight_change : float
        Δt, the change in the round-trip (pulse to echo) time, [s]
    sound_velocity : float
        V, the longitudinal velocity of sound in the unloaded bolt, [m/s]

    Returns
    -------
    float
        ΔL_U, [m]

    Notes
    -----
    [BoltMike] ch. 8: the time of flight is half the sound path duration, and the change in
    ultrasonic length is V times the change in time of flight.

    Examples
    --------
    40 ns more round trip at 5900 m/s: 5900 · 20e-9

    >>> round(ultrasonic_length_change(40e-9, 5900.0) * 1e6, 6)
    118.0
    """
    return sound_velocity * time_of_flight_change / 2.0


def time_of_flight_change(ultrasonic_length_change_: Any, sound_velocity: Any) -> Any:
    r"""Change in the echo's round-trip time for a change in ultrasonic length.

    .. math::
        \Delta t = \frac{2\,\Delta L_U}{V}

    Parameters
    ----------
    ultrasonic_length_change_ : float
        ΔL_U, [m]
    sound_velocity : float
        V, [m/s]

    Returns
    -------
    float
        Δt, [s]

    Notes
    -----
    [BoltMike] ch. 8, :func:`ultrasonic_length_change` solved for Δt.

    Examples
    --------
    >>> round(time_of_flight_change(118e-6, 5900.0) * 1e9, 6)
    40.0
    """
    return 2.0 * ultrasonic_length_change_ / sound_velocity


def thermal_length_change(
    ultrasonic_length: Any, temperature_factor: Any, temperature_change: Any
) -> Any:
    r"""Apparent change in ultrasonic length from a temperature change alone.

    .. math::
        \Delta L_{U,T} = \tau\,L_U\,\Delta T

    Parameters
    ----------
    ultrasonic_length : float
        L_U, the bolt's ultrasonic length at the zero reading, [m]
    temperature_factor : float
        τ, the relative change in ultrasonic length per kelvin (thermal expansion and the
        velocity's change together; [Dakota]'s T_F × 10⁻⁶), [1/K]
    temperature_change : float
        ΔT, the bolt's temperature at the loaded reading minus at the zero reading, [K]

    Returns
    -------
    float
        ΔL_U,T, [m]; subtracted from a measured ΔL_U to refer it to the zero reading's
        temperature

    Notes
    -----
    [Dakota]: T_F = (L_T − L_0)/(L_0 (T − T_0)) × 10⁶, a linear factor fitted per bolt
    material and geometry; this is that definition solved for L_T − L_0.

    Examples
    --------
    100 mm of bolt, τ = 100e-6 /K, 5 K warmer: 100 mm · 100e-6 · 5

    >>> round(thermal_length_change(0.1, 100e-6, 5.0) * 1e6, 6)
    50.0
    """
    return temperature_factor * ultrasonic_length * temperature_change


def mechanical_elongation(ultrasonic_length_change_: Any, stress_factor: Any) -> Any:
    r"""The bolt's mechanical elongation from its (temperature-referred) ultrasonic change.

    .. math::
        \Delta L = S_F\,\Delta L_U

    Parameters
    ----------
    ultrasonic_length_change_ : float
        ΔL_U at the zero reading's temperature, [m]
    stress_factor : float
        S_F, mechanical over ultrasonic change in length (< 1: sound slows under stress),
        calibrated per bolt material, [-]

    Returns
    -------
    float
        ΔL, [m]

    Notes
    -----
    [Dakota]: the sonic stress factor SSF = (L_M1 − L_M0)/(L_U1 − L_U0); elongation = change
    in time × velocity × stress factor. In acoustoelastic terms, with t ∝ L/v,
    L → L(1 + σ/E) and v → v(1 − kσ): S_F = 1/(1 + kE) to first order.

    Examples
    --------
    >>> round(mechanical_elongation(118e-6, 0.3) * 1e6, 6)
    35.4
    """
    return stress_factor * ultrasonic_length_change_


def ultrasonic_from_elongation(elongation_: Any, stress_factor: Any) -> Any:
    r"""The ultrasonic change in length that a mechanical elongation shows.

    .. math::
        \Delta L_U = \frac{\Delta L}{S_F}

    Parameters
    ----------
    elongation_ : float
        ΔL, [m]
    stress_factor : float
        S_F, [-]

    Returns
    -------
    float
        ΔL_U, [m]

    Notes
    -----
    [Dakota], :func:`mechanical_elongation` solved for ΔL_U.

    Examples
    --------
    >>> round(ultrasonic_from_elongation(35.4e-6, 0.3) * 1e6, 6)
    118.0
    """
    return elongation_ / stress_factor


__all__ = [
    "mechanical_elongation",
    "thermal_length_change",
    "time_of_flight_change",
    "ultrasonic_from_elongation",
    "ultrasonic_length_change",
]
