"""Hand-made houses for development: rooms, objects and words no generator writes, laid out by hand as a
user would write a scene. Writes handmade/<name>.json (a bakery and a boatyard, set H) and
handmade-J/<name>.json (a clinic, a farmhouse and a loft, set J: the kinds of house issue 18's reporter
made; sensor keys written as the schema's own examples spell them, "humidity", and "co2_ppm").

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


def clinic():
    rooms = [("reception", "reception", (0, 0), (6, 4)), ("consult", "consulting room", (6, 0), (12, 4)),
             ("treatment", "treatment room", (0, 4), (5, 10)), ("break", "staff break room", (5, 4), (12, 10))]
    segs = (with_gaps((0, 0), (12, 0), []) + with_gaps((0, 10), (12, 10), []) + with_gaps((0, 0), (0, 10), [])
            + with_gaps((12, 0), (12, 10), []) + with_gaps((6, 0), (6, 4), [(1.5, 2.5)])
            + with_gaps((0, 4), (12, 4), [(2.5, 3.5), (8.5, 9.5)]) + with_gaps((5, 4), (5, 10), [(7.5, 8.5)]))
    o = [
        obj("reception_desk_1", "reception desk", (3.0, 0.6, 0.55), (2.4, 0.8, 1.1), "reception", {"material": "birch"}),
        obj("sanitiser_1", "hand-sanitiser dispenser", (2.2, 0.6, 1.2), (0.15, 0.15, 0.3), "reception", {"colour": "white"}),
        obj("chair_1", "waiting-room chair", (0.5, 2.0, 0.45), (0.5, 0.5, 0.9), "reception", {"colour": "blue"}),
        obj("chair_2", "waiting-room chair", (0.5, 3.0, 0.45), (0.5, 0.5, 0.9), "reception", {"colour": "grey"}),
        obj("water_cooler_1", "water cooler", (5.6, 3.5, 0.6), (0.4, 0.4, 1.2), "reception", {"state": "switched on"}, {"temperature_c": 8}),
        obj("magazine_rack_1", "magazine rack", (4.5, 3.6, 0.5), (0.8, 0.3, 1.0), "reception", {"material": "chrome"}),
        obj("air_monitor_1", "air-quality monitor", (0.3, 0.4, 1.5), (0.1, 0.15, 0.15), "reception", {"state": "switched on"}, {"co2_ppm": 1150}),
        obj("ficus_1", "ficus", (5.5, 0.5, 0.6), (0.6, 0.6, 1.2), "reception", {"condition": "healthy"}, {"ndvi": 0.72}),
        obj("couch_1", "examination couch", (10.5, 1.0, 0.35), (2.0, 0.7, 0.7), "consult", {"colour": "teal"}),
        obj("gp_desk_1", "desk", (7.5, 3.4, 0.38), (1.4, 0.7, 0.76), "consult", {"material": "oak"}),
        obj("bp_monitor_1", "blood-pressure monitor", (7.2, 3.4, 0.85), (0.2, 0.15, 0.12), "consult", {"state": "switched off"}),
        obj("sharps_bin_1", "sharps bin", (11.7, 3.5, 0.2), (0.3, 0.3, 0.4), "consult", {"colour": "yellow"}),
        obj("lightbox_1", "x-ray lightbox", (11.9, 2.5, 1.4), (0.08, 0.8, 0.6), "consult", {"state": "switched on"}),
        obj("swivel_chair_1", "swivel chair", (8.5, 2.8, 0.45), (0.6, 0.6, 0.9), "consult", {"colour": "black"}),
        obj("med_fridge_1", "medicine fridge", (0.4, 5.0, 0.75), (0.6, 0.6, 1.5), "treatment", {"state": "locked"}, {"temperature_c": 5}),
        obj("autoclave_1", "autoclave", (1.5, 9.6, 1.05), (0.5, 0.4, 0.4), "treatment", {"state": "running"}, {"temperature_c": 121}),
        obj("worktop_1", "worktop", (2.0, 9.6, 0.43), (2.4, 0.6, 0.86), "treatment", {"material": "laminate"}),
        obj("trolley_1", "instrument trolley", (3.0, 7.0, 0.45), (0.8, 0.5, 0.9), "treatment", {"material": "stainless steel"}),
        obj("wheelchair_1", "wheelchair", (4.3, 5.2, 0.45), (0.7, 0.9, 0.9), "treatment", {"state": "folded"}),
        obj("drip_stand_1", "drip stand", (0.6, 8.0, 0.9), (0.4, 0.4, 1.8), "treatment", {"material": "chrome"}),
        obj("kettle_1", "kettle", (10.0, 9.7, 1.0), (0.25, 0.2, 0.25), "break", {"colour": "black", "state": "switched off"}, {"temperature_c": 22}),
        obj("counter_1", "counter", (10.0, 9.7, 0.45), (3.0, 0.6, 0.9), "break", {"colour": "white"}),
        obj("coffee_machine_1", "bean-to-cup coffee machine", (11.0, 9.7, 1.1), (0.35, 0.4, 0.4), "break", {"state": "switched on"}, {"temperature_c": 92}),
        obj("fridge_1", "fridge", (11.6, 6.0, 0.85), (0.7, 0.7, 1.7), "break", {"colour": "silver"}, {"temperature_c": 4}),
        obj("sofa_1", "two-seater sofa", (7.0, 5.0, 0.4), (1.6, 0.8, 0.8), "break", {"colour": "mustard"}),
        obj("noticeboard_1", "noticeboard", (5.1, 9.0, 1.4), (0.05, 1.0, 0.8), "break", {"material": "cork"}),
        obj("humidifier_1", "humidifier", (6.0, 9.6, 0.25), (0.3, 0.3, 0.5), "break", {"state": "switched on"}, {"humidity": 62}),
    ]
    return house("clinic", rooms, segs, o, (3.0, 2.0))


def farmhouse():
    rooms = [("kitchen", "farmhouse kitchen", (0, 0), (6, 5)), ("boot", "boot room", (6, 0), (9, 5)),
             ("parlour", "parlour", (9, 0), (14, 5)), ("pantry", "pantry", (0, 5), (4, 10)),
             ("potting", "potting room", (4, 5), (9, 10)), ("utility", "utility room", (9, 5), (14, 10))]
    segs = (with_gaps((0, 0), (14, 0), []) + with_gaps((0, 10), (14, 10), []) + with_gaps((0, 0), (0, 10), [])
            + with_gaps((14, 0), (14, 10), []) + with_gaps((6, 0), (6, 5), [(2, 3)]) + with_gaps((9, 0), (9, 5), [(2, 3)])
            + with_gaps((0, 5), (14, 5), [(2, 3), (6, 7), (11, 12)]) + with_gaps((4, 5), (4, 10), [])
            + with_gaps((9, 5), (9, 10), []))
    o = [
        obj("range_1", "range cooker", (1.0, 0.5, 0.45), (1.1, 0.7, 0.9), "kitchen", {"colour": "cream", "state": "lit"}, {"temperature_c": 180}),
        obj("sink_1", "butler sink", (3.0, 0.35, 0.45), (0.8, 0.6, 0.9), "kitchen", {"material": "ceramic"}),
        obj("dresser_1", "welsh dresser", (0.35, 3.5, 1.0), (0.5, 1.6, 2.0), "kitchen", {"material": "pine"}),
        obj("table_1", "kitchen table", (3.5, 3.2, 0.38), (2.0, 1.0, 0.76), "kitchen", {"material": "oak"}),
        obj("egg_basket_1", "egg basket", (3.2, 3.2, 0.85), (0.3, 0.3, 0.2), "kitchen", {"material": "wicker", "state": "full"}),
        obj("bread_bin_1", "bread bin", (4.8, 0.35, 1.0), (0.4, 0.3, 0.25), "kitchen", {"colour": "red"}),
        obj("boot_rack_1", "boot rack", (8.6, 4.0, 0.3), (0.5, 1.2, 0.6), "boot", {"material": "wooden"}),
        obj("freezer_1", "chest freezer", (7.5, 0.45, 0.45), (1.4, 0.7, 0.9), "boot", {"colour": "white"}, {"temperature_c": -18}),
        obj("dog_bed_1", "dog bed", (7.0, 4.2, 0.1), (0.9, 0.7, 0.2), "boot", {"colour": "tartan"}),
        obj("wood_burner_1", "wood burner", (13.6, 2.5, 0.5), (0.6, 0.6, 1.0), "parlour", {"state": "lit"}, {"temperature_c": 240}),
        obj("rocking_chair_1", "rocking chair", (12.0, 1.0, 0.5), (0.7, 0.9, 1.0), "parlour", {"material": "elm"}),
        obj("clock_1", "grandfather clock", (9.4, 4.6, 1.0), (0.5, 0.4, 2.0), "parlour", {"material": "mahogany"}),
        obj("piano_1", "upright piano", (10.2, 0.35, 0.6), (1.5, 0.6, 1.2), "parlour", {"colour": "black"}),
        obj("apple_crate_1", "apple crate", (0.5, 6.0, 0.2), (0.6, 0.4, 0.4), "pantry", {"variety": "bramley"}),
        obj("apple_crate_2", "apple crate", (0.5, 7.0, 0.2), (0.6, 0.4, 0.4), "pantry", {"variety": "cox"}),
        obj("cheese_press_1", "cheese press", (3.5, 9.5, 0.4), (0.5, 0.5, 0.8), "pantry", {"material": "oak"}),
        obj("shelf_1", "slate shelf", (1.5, 9.7, 0.45), (1.6, 0.5, 0.9), "pantry", {"material": "slate"}),
        obj("jar_1", "pickling jar", (1.2, 9.7, 1.0), (0.15, 0.15, 0.2), "pantry", {"state": "sealed"}),
        obj("bench_1", "potting bench", (6.5, 9.6, 0.45), (2.0, 0.7, 0.9), "potting", {"material": "wooden"}),
        obj("seed_tray_1", "seed tray", (6.0, 9.6, 0.95), (0.5, 0.3, 0.1), "potting", {"crop": "tomato"}, {"ndvi": 0.78}),
        obj("seed_tray_2", "seed tray", (7.0, 9.6, 0.95), (0.5, 0.3, 0.1), "potting", {"crop": "lettuce"}, {"ndvi": 0.31}),
        obj("propagator_1", "heated propagator", (8.5, 7.5, 0.4), (0.6, 0.4, 0.3), "potting", {"state": "switched on"}, {"temperature_c": 24, "humidity": 85}),
        obj("watering_can_1", "watering can", (4.5, 6.0, 0.2), (0.5, 0.2, 0.4), "potting", {"material": "galvanised"}),
        obj("washing_machine_1", "washing machine", (10.0, 9.6, 0.43), (0.6, 0.6, 0.86), "utility", {"state": "running"}, {"temperature_c": 40}),
        obj("dryer_1", "tumble dryer", (11.0, 9.6, 0.43), (0.6, 0.6, 0.86), "utility", {"state": "switched off"}, {"temperature_c": 20}),
        obj("cylinder_1", "hot-water cylinder", (13.6, 9.4, 0.8), (0.6, 0.6, 1.6), "utility", {"state": "switched on"}, {"temperature_c": 60}),
        obj("clothes_horse_1", "clothes horse", (12.0, 6.5, 0.6), (1.0, 0.5, 1.2), "utility", {"material": "wooden"}),
    ]
    return house("farmhouse", rooms, segs, o, (3.0, 2.0))


def loft():
    rooms = [("living", "living area", (0, 0), (7, 5)), ("sleeping", "sleeping area", (7, 0), (12, 5)),
             ("studio", "studio", (0, 5), (6, 9)), ("bathroom", "bathroom", (6, 5), (9, 9)),
             ("kitchenette", "kitchenette", (9, 5), (12, 9))]
    segs = (with_gaps((0, 0), (12, 0), []) + with_gaps((0, 9), (12, 9), []) + with_gaps((0, 0), (0, 9), [])
            + with_gaps((12, 0), (12, 9), []) + with_gaps((7, 0), (7, 5), [(1, 3.5)])
            + with_gaps((0, 5), (12, 5), [(2, 4), (7, 8), (10, 11)]) + with_gaps((6, 5), (6, 9), [])
            + with_gaps((9, 5), (9, 9), []))
    o = [
        obj("sofa_1", "corner sofa", (1.5, 0.6, 0.4), (2.6, 0.9, 0.8), "living", {"colour": "charcoal"}),
        obj("sideboard_1", "sideboard", (5.0, 0.3, 0.4), (1.6, 0.45, 0.8), "living", {"material": "walnut"}),
        obj("record_player_1", "record player", (4.6, 0.3, 0.88), (0.45, 0.35, 0.15), "living", {"state": "switched off"}),
        obj("arc_lamp_1", "arc lamp", (0.4, 2.5, 0.9), (0.4, 0.4, 1.8), "living", {"state": "switched on"}),
        obj("coffee_table_1", "coffee table", (1.5, 2.0, 0.2), (1.2, 0.6, 0.4), "living", {"material": "concrete"}),
        obj("bean_bag_1", "bean bag", (4.0, 3.5, 0.25), (0.8, 0.8, 0.5), "living", {"colour": "mustard"}),
        obj("fig_1", "fiddle-leaf fig", (6.5, 0.5, 0.8), (0.6, 0.6, 1.6), "living", {"condition": "drooping"}, {"ndvi": 0.28}),
        obj("projector_1", "projector", (0.3, 4.5, 1.6), (0.3, 0.25, 0.12), "living", {"state": "switched off"}),
        obj("bed_1", "platform bed", (10.0, 1.2, 0.2), (2.0, 2.2, 0.4), "sleeping", {"colour": "white"}),
        obj("wardrobe_1", "wardrobe", (11.7, 3.8, 1.0), (0.6, 1.4, 2.0), "sleeping", {"material": "oak"}),
        obj("rail_1", "clothes rail", (8.8, 3.3, 0.8), (0.4, 1.2, 1.6), "sleeping", {"material": "copper"}),
        obj("bedside_table_1", "bedside table", (8.6, 0.3, 0.25), (0.4, 0.4, 0.5), "sleeping", {"material": "oak"}),
        obj("bedside_lamp_1", "bedside lamp", (8.6, 0.3, 0.65), (0.2, 0.2, 0.3), "sleeping", {"state": "switched on"}),
        obj("dehumidifier_1", "dehumidifier", (11.6, 0.4, 0.3), (0.35, 0.3, 0.6), "sleeping", {"state": "running"}, {"humidity": 48}),
        obj("easel_1", "easel", (1.0, 6.0, 0.9), (0.6, 0.6, 1.8), "studio", {"material": "beech"}),
        obj("drafting_table_1", "drafting table", (3.0, 8.5, 0.45), (1.4, 0.9, 0.9), "studio", {"material": "steel"}),
        obj("printer_1", "3D printer", (5.4, 8.6, 0.25), (0.5, 0.5, 0.5), "studio", {"state": "printing"}, {"temperature_c": 210}),
        obj("kiln_1", "pottery kiln", (5.4, 6.0, 0.5), (0.7, 0.7, 1.0), "studio", {"state": "switched off"}, {"temperature_c": 25}),
        obj("monstera_1", "monstera", (0.5, 8.5, 0.6), (0.6, 0.6, 1.2), "studio", {"condition": "thriving"}, {"ndvi": 0.81}),
        obj("bath_1", "roll-top bath", (7.5, 8.2, 0.3), (1.6, 0.75, 0.6), "bathroom", {"colour": "white"}),
        obj("towel_rail_1", "heated towel rail", (8.9, 6.0, 0.8), (0.08, 0.6, 1.0), "bathroom", {"state": "switched on"}, {"temperature_c": 45}),
        obj("basin_1", "basin", (6.3, 6.5, 0.4), (0.45, 0.6, 0.8), "bathroom", {"material": "ceramic"}),
        obj("espresso_1", "espresso machine", (11.7, 8.6, 1.05), (0.4, 0.35, 0.4), "kitchenette", {"state": "switched on"}, {"temperature_c": 93}),
        obj("worktop_1", "worktop", (11.7, 7.5, 0.45), (0.6, 2.5, 0.9), "kitchenette", {"material": "concrete"}),
        obj("fridge_freezer_1", "fridge-freezer", (9.4, 8.6, 0.9), (0.7, 0.7, 1.8), "kitchenette", {"colour": "silver"}, {"temperature_c": 3}),
        obj("stool_1", "bar stool", (10.6, 6.5, 0.4), (0.4, 0.4, 0.8), "kitchenette", {"material": "metal"}),
        obj("stool_2", "bar stool", (10.6, 7.5, 0.4), (0.4, 0.4, 0.8), "kitchenette", {"material": "wooden"}),
    ]
    return house("loft", rooms, segs, o, (3.0, 2.0))


if __name__ == "__main__":
    for sub, houses in (("handmade", (bakery(), boatyard())), ("handmade-J", (clinic(), farmhouse(), loft()))):
        out = OUT.parent / sub
        out.mkdir(parents=True, exist_ok=True)
        for s in houses:
            (out / f"{s['name']}.json").write_text(json.dumps(s, indent=1) + "\n")
            print(out / f"{s['name']}.json")
