"""Two hand-made houses for development (a bakery and a boatyard): rooms, objects and words no generator
writes, laid out by hand as a user would write a scene. Writes handmade/<name>.json.

    python experiments/devsets/make_handmade.py
"""

import json
from pathlib import Path

OUT = Path(__file__).resolve().parent / "handmade"


def walls(segments):
    return [{"a": list(a), "b": list(b), "thickness": 0.1, "height": 2.5} for a, b in segments]


def with_gaps(a, b, gaps):
    """Wall segments along a -> b (axis-aligned) leaving door gaps [(lo, hi), ...] along the varying axis."""
    ax = 0 if a[1] == b[1] else 1
    lo, hi = sorted((a[ax], b[ax]))
    cuts, cur = [], lo
    for g0, g1 in sorted(gaps):
        cuts.append((cur, g0))
        cur = g1
    cuts.append((cur, hi))
    out = []
    for c0, c1 in cuts:
        if c1 - c0 > 1e-6:
            p, q = list(a), list(a)
            p[ax], q[ax] = c0, c1
            out.append((tuple(p), tuple(q)))
    return out


def obj(i, cat, xyz, size, room, attrs=None, sensors=None):
    o = {"id": i, "category": cat, "position": list(xyz), "size": list(size), "room": room}
    if attrs:
        o["attributes"] = attrs
    if sensors:
        o["sensors"] = sensors
    return o


def house(name, rooms, segs, objects, start):
    return {"format": "ragnav-scene/1", "name": name,
            "rooms": [{"id": i, "type": t, "min": list(a), "max": list(b)} for i, t, a, b in rooms],
            "walls": walls(segs), "objects": objects, "start": {"position": list(start), "yaw": 0.0}}


def bakery():
    rooms = [("bakehouse", "bakehouse", (0, 0), (6, 5)), ("shop", "shop floor", (6, 0), (11, 5)),
             ("store", "flour store", (0, 5), (5, 9)), ("staff", "staff room", (5, 5), (11, 9))]
    segs = (with_gaps((0, 0), (11, 0), []) + with_gaps((0, 9), (11, 9), []) + with_gaps((0, 0), (0, 9), [])
            + with_gaps((11, 0), (11, 9), []) + with_gaps((6, 0), (6, 5), [(2, 3)])
            + with_gaps((0, 5), (11, 5), [(2, 3), (8, 9)]) + with_gaps((5, 5), (5, 9), [(6.5, 7.5)]))
    o = [
        obj("bread_oven_1", "bread oven", (1.0, 0.6, 0.8), (1.6, 1.0, 1.6), "bakehouse", {"state": "switched on"}, {"temperature_c": 220}),
        obj("dough_mixer_1", "dough mixer", (4.0, 0.5, 0.6), (0.8, 0.7, 1.2), "bakehouse", {"colour": "white", "state": "switched off"}, {"temperature_c": 21}),
        obj("proving_cabinet_1", "proving cabinet", (5.4, 2.0, 0.9), (0.8, 0.8, 1.8), "bakehouse", {"material": "steel"}, {"temperature_c": 32, "humidity_pct": 80}),
        obj("work_table_1", "work table", (3.0, 3.0, 0.45), (2.0, 1.0, 0.9), "bakehouse", {"material": "stainless steel"}),
        obj("rolling_pin_1", "rolling pin", (3.3, 3.0, 0.93), (0.45, 0.06, 0.06), "bakehouse", {"material": "beech"}),
        obj("cooling_rack_1", "cooling rack", (0.5, 4.0, 0.85), (0.6, 1.2, 1.7), "bakehouse", {"state": "full"}),
        obj("display_counter_1", "display counter", (8.5, 1.0, 0.5), (2.5, 0.8, 1.0), "shop", {"material": "glass"}),
        obj("cash_register_1", "cash register", (9.5, 1.0, 1.15), (0.4, 0.4, 0.3), "shop", {"colour": "black"}),
        obj("bread_basket_1", "bread basket", (7.0, 4.3, 0.3), (0.6, 0.4, 0.6), "shop", {"material": "wicker", "state": "full"}),
        obj("bread_basket_2", "bread basket", (8.0, 4.3, 0.3), (0.6, 0.4, 0.6), "shop", {"material": "wicker", "state": "empty"}),
        obj("coffee_grinder_1", "coffee grinder", (10.5, 4.4, 0.25), (0.3, 0.3, 0.5), "shop", {"colour": "red"}),
        obj("display_fridge_1", "display fridge", (10.6, 2.5, 0.95), (0.7, 0.7, 1.9), "shop", {"state": "switched on"}, {"temperature_c": 4}),
        obj("flour_sack_1", "flour sack", (0.6, 6.0, 0.4), (0.5, 0.4, 0.8), "store", {"kind": "wholemeal"}),
        obj("flour_sack_2", "flour sack", (0.6, 7.5, 0.4), (0.5, 0.4, 0.8), "store", {"kind": "white"}),
        obj("sack_truck_1", "sack truck", (3.0, 8.5, 0.6), (0.5, 0.6, 1.2), "store", {"colour": "blue"}),
        obj("dehumidifier_1", "dehumidifier", (4.4, 5.6, 0.3), (0.4, 0.3, 0.6), "store", {"state": "switched on"}, {"humidity_pct": 45}),
        obj("shelving_rack_1", "shelving rack", (1.8, 8.6, 0.9), (1.6, 0.5, 1.8), "store", {"material": "metal"}),
        obj("counter_1", "kitchenette counter", (9.5, 8.6, 0.45), (2.4, 0.6, 0.9), "staff", {"colour": "grey"}),
        obj("kettle_1", "kettle", (9.0, 8.6, 1.0), (0.25, 0.2, 0.25), "staff", {"colour": "white", "state": "switched on"}, {"temperature_c": 95}),
        obj("microwave_1", "microwave", (10.2, 8.6, 1.05), (0.5, 0.4, 0.3), "staff", {"colour": "silver"}),
        obj("coat_stand_1", "coat stand", (10.6, 5.5, 0.9), (0.4, 0.4, 1.8), "staff", {"material": "wood"}),
        obj("armchair_1", "armchair", (7.0, 7.5, 0.45), (0.8, 0.8, 0.9), "staff", {"colour": "green", "material": "leather"}),
        obj("first_aid_kit_1", "first aid kit", (5.2, 8.5, 1.5), (0.1, 0.4, 0.3), "staff", {"colour": "green"}),
        obj("potted_fern_1", "fern", (6.0, 5.5, 0.35), (0.5, 0.5, 0.7), "staff", {"condition": "healthy"}, {"ndvi": 0.75}),
    ]
    return house("bakery", rooms, segs, o, (3.0, 1.8))


def boatyard():
    rooms = [("shed", "boat shed", (0, 0), (8, 6)), ("chandlery", "chandlery", (8, 0), (12, 6)),
             ("office", "office", (0, 6), (5, 10)), ("changing", "changing room", (5, 6), (12, 10))]
    segs = (with_gaps((0, 0), (12, 0), []) + with_gaps((0, 10), (12, 10), []) + with_gaps((0, 0), (0, 10), [])
            + with_gaps((12, 0), (12, 10), []) + with_gaps((8, 0), (8, 6), [(3, 4)])
            + with_gaps((0, 6), (12, 6), [(3, 4), (6.5, 7.5)]) + with_gaps((5, 6), (5, 10), [(8, 9)]))
    o = [
        obj("rowing_boat_1", "rowing boat", (2.5, 2.0, 0.4), (4.0, 1.4, 0.8), "shed", {"material": "wooden"}),
        obj("kayak_1", "kayak", (6.0, 0.5, 0.2), (3.0, 0.6, 0.4), "shed", {"colour": "yellow"}),
        obj("kayak_2", "kayak", (5.5, 3.9, 0.2), (3.0, 0.6, 0.4), "shed", {"colour": "red"}),
        obj("outboard_motor_1", "outboard motor", (0.5, 4.5, 0.6), (0.5, 0.4, 1.2), "shed", {"state": "switched off"}, {"temperature_c": 18}),
        obj("life_jacket_rack_1", "life jacket rack", (0.4, 0.6, 0.8), (0.5, 1.0, 1.6), "shed", {"colour": "orange"}),
        obj("workbench_1", "workbench", (1.6, 5.55, 0.45), (2.0, 0.7, 0.9), "shed", {"material": "oak"}),
        obj("varnish_tin_1", "varnish tin", (1.1, 5.55, 0.98), (0.2, 0.2, 0.15), "shed", {"state": "open"}),
        obj("heat_gun_1", "heat gun", (2.1, 5.55, 0.98), (0.3, 0.1, 0.15), "shed", {"state": "switched on"}, {"temperature_c": 310}),
        obj("cash_desk_1", "cash desk", (10.0, 0.5, 0.5), (2.0, 0.7, 1.0), "chandlery", {"material": "pine"}),
        obj("chart_table_1", "chart table", (10.5, 4.5, 0.45), (1.6, 1.0, 0.9), "chandlery", {"material": "teak"}),
        obj("barometer_1", "barometer", (11.9, 3.0, 1.6), (0.1, 0.3, 0.3), "chandlery", {"material": "brass"}),
        obj("rope_coil_1", "rope coil", (8.6, 5.4, 0.1), (0.6, 0.6, 0.2), "chandlery", {"colour": "blue"}),
        obj("rope_coil_2", "rope coil", (9.4, 5.4, 0.1), (0.6, 0.6, 0.2), "chandlery", {"colour": "white"}),
        obj("water_heater_1", "water heater", (11.6, 9.6, 0.8), (0.6, 0.6, 1.6), "changing", {"state": "switched on"}, {"temperature_c": 60}),
        obj("locker_1", "locker", (6.5, 9.7, 0.9), (0.5, 0.5, 1.8), "changing", {"state": "open"}),
        obj("locker_2", "locker", (7.2, 9.7, 0.9), (0.5, 0.5, 1.8), "changing", {"state": "closed"}),
        obj("bench_1", "bench", (9.0, 8.0, 0.25), (2.0, 0.4, 0.5), "changing", {"material": "wooden"}),
        obj("drying_cabinet_1", "drying cabinet", (11.6, 7.0, 0.9), (0.6, 0.6, 1.8), "changing", {"state": "switched on"}, {"temperature_c": 45, "humidity_pct": 30}),
        obj("desk_1", "desk", (2.5, 9.5, 0.4), (1.6, 0.8, 0.8), "office", {"material": "oak"}),
        obj("laptop_1", "laptop", (2.3, 9.5, 0.82), (0.35, 0.25, 0.03), "office", {"state": "switched on"}, {"temperature_c": 38}),
        obj("filing_cabinet_1", "filing cabinet", (0.4, 8.0, 0.65), (0.5, 0.6, 1.3), "office", {"colour": "grey", "state": "closed"}),
        obj("potted_fern_1", "fern", (4.5, 6.5, 0.35), (0.5, 0.5, 0.7), "office", {"condition": "wilting"}, {"ndvi": 0.2}),
        obj("potted_fern_2", "fern", (0.5, 9.5, 0.35), (0.5, 0.5, 0.7), "office", {"condition": "healthy"}, {"ndvi": 0.7}),
        obj("radiator_1", "radiator", (4.9, 8.0, 0.4), (0.1, 1.0, 0.6), "office", {"colour": "white"}, {"temperature_c": 45}),
    ]
    return house("boatyard", rooms, segs, o, (6.0, 2.0))


if __name__ == "__main__":
    OUT.mkdir(parents=True, exist_ok=True)
    for s in (bakery(), boatyard()):
        (OUT / f"{s['name']}.json").write_text(json.dumps(s, indent=1) + "\n")
        print(OUT / f"{s['name']}.json")
