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

# Unit codes of the parser (`parser._unit_code`) -> the reading a bare number with that unit measures.
UNIT_READING = {"c": "temperature_c", "f": "temperature_c", "%": "humidity_pct", "ppm": "co2_ppm", "db": "noise_db",
                "lux": "light_lux", "w": "power_w", "kw": "power_w", "kg": "weight_kg", "hpa": "pressure_hpa"}

# Unit words that end a scene key -> (scale, offset) to the canonical unit, and the reading they imply alone.
_KEY_UNITS: dict[str, tuple[float, float, str | None]] = {
    **dict.fromkeys(("c", "degc", "celsius", "centigrade"), (1.0, 0.0, "temperature_c")),
    **dict.fromkeys(("f", "degf", "fahrenheit"), (5.0 / 9.0, -32.0 * 5.0 / 9.0, "temperature_c")),
    **dict.fromkeys(("k", "kelvin"), (1.0, -273.15, "temperature_c")),
    **dict.fromkeys(("pct", "percent", "perc", "%"), (1.0, 0.0, None)),
    "ppm": (1.0, 0.0, "co2_ppm"),
    **dict.fromkeys(("db", "dba", "decibels"), (1.0, 0.0, "noise_db")),
    **dict.fromkeys(("lux", "lx"), (1.0, 0.0, "light_lux")),
    **dict.fromkeys(("w", "watts"), (1.0, 0.0, "power_w")),
    "kw": (1000.0, 0.0, "power_w"),
    **dict.fromkeys(("kg", "kilograms", "kilos"), (1.0, 0.0, "weight_kg")),
    **dict.fromkeys(("g", "grams"), (0.001, 0.0, "weight_kg")),
    **dict.fromkeys(("hpa", "mbar", "millibars"), (1.0, 0.0, "pressure_hpa")),
}
_WORDS = re.compile(r"[a-z0-9%]+")


def canonical_sensor(key: str, value: float) -> tuple[str, float]:
    """(canonical key, value in its unit) of a scene's sensor `key: value`: the key's words (split at
    '_', '-', spaces) less a trailing unit name the reading names of `lexicon.READING_NAMES` know, else the
    reading its unit implies ("ppm"); a key neither names is kept as written. Idempotent on canonical keys."""
    if key in READINGS:
        return key, float(value)
    words = _WORDS.findall(key.lower())
    scale, offset, implied = 1.0, 0.0, None
    if len(words) > 1 and words[-1] in _KEY_UNITS or len(words) == 1 and words[0] in _KEY_UNITS and _KEY_UNITS[words[0]][2]:
        scale, offset, implied = _KEY_UNITS[words[-1]]
        words = words[:-1]
    name = " ".join(words)
    rd = READING_NAMES.get(name) or (implied if not name else None)
    if rd is None:
        return key, float(value)
    if implied is not None and implied != rd:  # "temperature_ppm": a unit of another reading; keep it as written
        return key, float(value)
    return rd, round(float(value) * scale + offset, 6)
