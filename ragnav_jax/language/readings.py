"""Sensor readings: the canonical keys, their tolerances, units as written and scene keys as users spell them.

A scene's `sensors` are "named scalar readings" with an open key (the schema's own examples are
`temperature_c`, `ndvi` and `humidity`). A reading the robot is asked about must meet the one the scene
holds, whatever either is called, so both sides go through this module:

    canonical_sensor("humidity", 62)       # ("humidity_pct", 62.0)
    canonical_sensor("temp_f", 98.6)       # ("temperature_c", 37.0): converted to the canonical unit
    canonical_sensor("co2", 900)           # ("co2_ppm", 900.0)
    canonical_sensor("vibration_mm_s", 3)  # ("vibration_mm_s", 3.0): a reading nobody named stays as written

The parser names readings by the words of `lexicon.READING_NAMES` and infers them from a unit
(`UNIT_READING`: "ppm" is CO2, "dB" noise); the generator writes only the first three keys.
"""

from __future__ import annotations

import dataclasses
import re

from ragnav_jax.language.lexicon import READING_NAMES


@dataclasses.dataclass(frozen=True)
class Reading:
    text: str  # what the reading is called in generated sentences and captions
    tolerance: float  # "about v" holds within this of v; also the retrieval kernel's sensor scale


READINGS: dict[str, Reading] = {
    "temperature_c": Reading("temperature", 3.0),
    "ndvi": Reading("NDVI", 0.05),
    "humidity_pct": Reading("humidity", 5.0),
    "co2_ppm": Reading("CO2", 100.0),
    "noise_db": Reading("noise level", 3.0),
    "light_lux": Reading("light level", 50.0),
    "battery_pct": Reading("battery level", 5.0),
    "power_w": Reading("power draw", 10.0),
    "weight_kg": Reading("weight", 1.0),
    "pressure_hpa": Reading("pressure", 5.0),
}

# Units as written (in sentences, and as the last word of a scene key) -> unit code.
UNIT_CODES: dict[str, str] = {
    **dict.fromkeys(("c", "degc", "celsius", "centigrade"), "c"),
    **dict.fromkeys(("f", "degf", "fahrenheit"), "f"),
    **dict.fromkeys(("k", "kelvin"), "k"),
    **dict.fromkeys(("%", "pct", "percent", "per cent", "perc"), "%"),
    **dict.fromkeys(("ppm", "parts per million"), "ppm"),
    **dict.fromkeys(("db", "dba", "decibel", "decibels"), "db"),
    **dict.fromkeys(("lux", "lx"), "lux"),
    **dict.fromkeys(("w", "watt", "watts"), "w"),
    **dict.fromkeys(("kw", "kilowatt", "kilowatts"), "kw"),
    **dict.fromkeys(("kg", "kilo", "kilos", "kilogram", "kilograms"), "kg"),
    **dict.fromkeys(("g", "grams"), "g"),
    **dict.fromkeys(("hpa", "mbar", "millibar", "millibars"), "hpa"),
}
# Unit code -> the reading a number in that unit measures (none for %: humidity, battery, ...).
UNIT_READING = {"c": "temperature_c", "f": "temperature_c", "k": "temperature_c", "ppm": "co2_ppm", "db": "noise_db",
                "lux": "light_lux", "w": "power_w", "kw": "power_w", "kg": "weight_kg", "g": "weight_kg",
                "hpa": "pressure_hpa"}
# Unit code -> (scale, offset) to the canonical unit of its reading.
TO_CANONICAL = {"f": (5.0 / 9.0, -32.0 * 5.0 / 9.0), "k": (1.0, -273.15), "kw": (1000.0, 0.0), "g": (0.001, 0.0)}


def to_canonical(value: float, code: str) -> float:
    """A value written in unit `code` in its reading's canonical unit (98.6 F -> 37 C, 1.5 kW -> 1500 W)."""
    scale, offset = TO_CANONICAL.get(code, (1.0, 0.0))
    return round(value * scale + offset, 6)


_WORDS = re.compile(r"[a-z0-9%]+")


def canonical_sensor(key: str, value: float) -> tuple[str, float]:
    """(canonical key, value in its unit) of a scene's sensor `key: value`: the key's words (split at
    '_', '-', spaces) less a trailing unit name the reading names of `lexicon.READING_NAMES` know, else the
    reading its unit implies ("ppm"); a key neither names is kept as written. Idempotent on canonical keys."""
    if key in READINGS:
        return key, float(value)
    words = _WORDS.findall(key.lower())
    code = UNIT_CODES.get(words[-1]) if words else None
    if code is None or len(words) == 1 and code not in UNIT_READING:
        code = ""  # no unit written ("humidity"), or a bare "%" that names no reading
    else:
        words = words[:-1]
    implied = UNIT_READING.get(code)
    rd = READING_NAMES.get(" ".join(words)) if words else implied
    if rd is None or implied is not None and implied != rd:  # unnamed, or "temperature_ppm": keep it as written
        return key, float(value)
    return rd, to_canonical(float(value), code)
