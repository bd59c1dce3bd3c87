"""The shape of the Python API: the naming rule, pickling, errors with
fields, tasks of four and five poses, Grid, DesignLimits and Pivot records."""

import copy
import inspect
import math
import multiprocessing
import pickle
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import burmester
from burmester import (
    AssemblyError,
    CoincidencePoint,
    Conic,
    Cubic,
    CurveDyad,
    DegenerateError,
    DesignLimits,
    Filemon,
    FourBar,
    Grid,
    InvalidInputError,
    LinkageFigures,
    Pivot,
    Pole,
    SolutionMap,
    SynthesizedFourBar,
    Task,
)
from conftest import C0, POSES, VP

FOUR = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1), (4.0, 2.0, 1.1)]  # poses 3 and 4: a translation
FIVE = FOUR + [(1.0, 3.0, 2.0)]
FREE_PIVOT = (-7.98, -5.18)
# Five poses with four Burmester points (shared/notes/positions-4-5.md, section 6).
BURMESTER_FIVE = [(x, y, math.radians(a)) for x, y, a in [
    (1.049199280691, 2.279426358634, 45.220037141544), (0.734502065472, 3.198658887874, 26.633426990744),
    (-0.378159188147, 3.063048993013, 21.786789298262), (-1.268710439724, 2.051150142014, 27.048624103934),
    (-1.411118156972, 0.597429126400, 48.044287536536)]]


def samples():
    """One object of every class (tasks of 3, 4 and 5 poses)."""
    t = Task(POSES)
    f = t.filemon(C0)
    sfb = f.four_bar(FREE_PIVOT)
    fb = sfb.fourbar
    smap = f.solution_map(Grid(*VP, 24, 20), base_plate=[(-8, -8), (8, -8), (8, 8), (-8, 8)],
                          obstacles=[[(0.0, -3.0), (1.0, -3.0), (0.5, -2.0)]], link_width=0.1,
                          travel_samples=16, limits=DesignLimits(25.0, 8.0, "any"))
    driven = t.driven_solution_map((-3.0, 4.0), Grid(*VP, 20, 16))
    (pivot,) = smap.best_pivots(1)
    atlas = burmester.pivot_atlas(t, (-6.0, 6.0, -6.0, 6.0, 4, 3), Grid(*VP, 16, 16), link_width=0.1)
    space = burmester.Space(pivot_box=(-6.0, 6.0, -6.0, 6.0), link_width=0.1)
    report = burmester.design(t, space=space, coarse_driven=4, coarse_driving=12, starts=4)
    misses = burmester.design(t, limits=DesignLimits(85.0), coarse_driven=4, coarse_driving=12, starts=2)
    pmap = Task(BURMESTER_FIVE[:4]).pair_map(40, 36, min_transmission_deg=20.0,
                                             base_plate=[(-20, -20), (20, -20), (20, 20), (-20, 20)])
    # A motor for the example's best linkage by transmission (its input swings).
    rocker = f.solution_map(Grid(*VP, 100, 100)).best_pivots(1, rank_by="transmission")[0].linkage
    a0 = rocker.driving[0]
    dmap = rocker.drive_map(a0[0] - 40, a0[0] + 40, a0[1] - 40, a0[1] + 40, 24, 20, min_transmission_deg=10,
                            base_plate=[(a0[0] - 50, a0[1] - 50), (a0[0] + 50, a0[1] - 50), (a0[0], a0[1] + 50)],
                            obstacles=[[(0.0, -3.0), (1.0, -3.0), (0.5, -2.0)]], link_width=0.1, travel_samples=16)
    valid = [(j, i) for j in range(20) for i in range(24) if dmap.valid[j, i]]
    # A slider point of t (on the image-pole circle) and its guide.
    ipc = t.image_pole_circle()
    b1 = (ipc["center"][0] + ipc["radius"], ipc["center"][1])
    b3 = t.displace(b1, 1, 3)
    slider = burmester.SliderFilemon(t, b1, (b3[0] - b1[0], b3[1] - b1[1]))
    amap = rocker.actuator_map(*VP, 24, 24)
    return {
        "Grid": Grid(*VP, 30, 20),
        "Conic": f.conics[0],
        "Conic (built)": Conic(1, 0, -1, 0, 0, -1),
        "Cubic": Task(FOUR).center_point_curve(),
        "Cubic (built)": Cubic([0.0, -1.0, 0.0, 0.0, 0.0, -1.0, 1.0, 0.0, 0.0, 0.0]),
        "CoincidencePoint": Task(FOUR).coincidence_points()[0],
        "CoincidencePoint (at infinity)": Task(FOUR).coincidence_points()[-1],
        "CurveDyad": Task(FOUR).curve_dyads(8)[0][0],
        "SynthesizedFourBar (5 poses)": Task(BURMESTER_FIVE).burmester_four_bars()[0][2],
        "SynthesizedFourBar (4 poses)": Task(BURMESTER_FIVE[:4]).four_bar((0.0, 0.0), (4.0, 0.0)),
        "FourBar": FourBar(ground=100.0, crank=40.0, coupler=120.0, rocker=80.0, origin=(1.0, 2.0), ground_angle=0.3),
        "Configuration": fb.configuration(sfb.input_angles[0], "open"),
        "LinkageFigures": sfb.figures,
        "Pole": t.poles[0],
        "Pole (at infinity)": Task(FOUR).poles[-1],
        "Task": t,
        "Task (4 poses)": Task(FOUR),
        "Task (5 poses)": Task(FIVE),
        "SliderDyad": Task(POSES).slider_dyads(5)[2],
        "InvertedSlider": Task(POSES).inverted_sliders(5)[2],
        "Filemon": f,
        "SliderFilemon": slider,
        "SynthesizedFourBar": sfb,
        "DesignLimits": DesignLimits(35.5, 4.0, "rocker"),
        "Pivot": pivot,
        "SolutionMap": smap,
        "SolutionMap (driven)": driven,
        "PivotAtlas": atlas,
        "Space": space,
        "DesignReport": report,
        "Design": report[0],
        "NearMiss": misses.near_misses[0],
        "AtlasPair": atlas.best_pairs(1)[0],
        "PairMap": pmap,
        "Pair": pmap.best_pairs(1)[0],
        "DriveMap": dmap,
        "Drive": dmap.drive(*valid[len(valid) // 2]),
        "Drive (best)": rocker.best_drive(),
        "SixBar": rocker.best_drive().sixbar,
        "ActuatorMap": amap,
        "Actuator": amap.placement(*np.argwhere(amap.valid)[0]),
    }


CLASSES = [Grid, Conic, Cubic, CoincidencePoint, CurveDyad, FourBar, burmester.Configuration, LinkageFigures, Pole,
           Task, Filemon, SynthesizedFourBar, DesignLimits, Pivot, SolutionMap, burmester.PivotAtlas,
           burmester.AtlasPair, burmester.PairMap, burmester.Pair, burmester.Space, burmester.Design,
           burmester.NearMiss, burmester.DesignReport,
           burmester.SixBar, burmester.Drive, burmester.DriveMap,
           burmester.SliderFilemon, burmester.Actuator, burmester.ActuatorMap]

# Slider linkages (issue 27): their samples, classes, properties and methods.
_SLIDER_TASK = [(0.0, 0.0, 0.0), (2.0, 0.5, 0.4), (3.0, 2.0, 1.1)]


def _slider_samples():
    sc = burmester.SliderCrank(crank=1.0, coupler=3.0, guide_point=(0.0, 0.4), guide=(math.cos(0.2), math.sin(0.2)))
    t, poses = None, []
    for t2 in (0.2, 1.0, 2.1, 3.0):
        c = sc.solve(t2)
        x, y = sc.coupler_point(t2, (0.5, 0.7))
        poses.append((x, y, c.theta3 + 0.3))
    t = Task(poses)
    _, a1, b1 = sc.joints(0.2)
    return {
        "SliderCrank": sc,
        "SliderConfiguration": sc.solve(0.7, "crossed"),
        "SynthesizedSliderCrank": t.slider_crank(((0.0, 0.0), a1), (b1, sc.guide)),
    }


_samples_base = samples


def samples():  # noqa: F811 (the base samples and the slider linkages')
    return {**_samples_base(), **_slider_samples()}


CLASSES += [burmester.SliderCrank, burmester.SliderConfiguration, burmester.SynthesizedSliderCrank]
CLASSES += [burmester.SliderDyad, burmester.InvertedSlider]  # issue 27 (ssynth27)


# The inverted slider-crank (issue 27, inv31).
def _inverted_samples():
    q = burmester.InvertedSliderCrank(crank=100.0, swivel=(30.0, -300.0), offset=12.0)
    poses = []
    for t2 in (-0.4, 0.3, 1.1):
        c = q.solve(t2)
        x, y = q.coupler_point(t2, (180.0, 40.0))
        poses.append((x, y, c.theta3 + 0.4))
    t = Task(poses)
    inv = t.inverted_slider((30.0, -300.0))
    _, a1, _, _ = q.joints(-0.4)
    return {
        "InvertedSliderCrank": q,
        "InvertedConfiguration": q.solve(0.7, "crossed"),
        "SynthesizedInvertedSliderCrank": t.inverted_slider_crank(((0.0, 0.0), a1), (inv.swivel, inv.direction)),
    }


_samples_slider = samples


def samples():  # noqa: F811 (the samples so far and the inverted slider-crank's)
    return {**_samples_slider(), **_inverted_samples()}


CLASSES += [burmester.InvertedSliderCrank, burmester.InvertedConfiguration, burmester.SynthesizedInvertedSliderCrank]


# A ranked pivot of a solution map with a driven slider (issue 27, srank32).
def _slider_pivot_samples():
    from test_slider_branch import U, _press_task

    task, b1 = _press_task()
    smap = burmester.SliderFilemon(task, b1, U).solution_map(Grid(-300.0, 300.0, -300.0, 300.0, 21, 21))
    return {"SliderPivot": smap.best_slider_pivots(1)[0]}


_samples_inverted = samples


def samples():  # noqa: F811 (the samples so far and the slider map's pivots)
    return {**_samples_inverted(), **_slider_pivot_samples()}


CLASSES += [burmester.SliderPivot]


# ---------------------------------------------------------------------------
# Pickling


@pytest.mark.parametrize("name", list(samples()))
def test_every_class_pickles_to_an_equal_object(name):
    obj = samples()[name]
    for protocol in range(2, pickle.HIGHEST_PROTOCOL + 1):
        back = pickle.loads(pickle.dumps(obj, protocol=protocol))
        assert type(back) is type(obj)
        assert back == obj, (name, protocol)
        assert repr(back) == repr(obj)
    assert copy.copy(obj) == obj and copy.deepcopy(obj) == obj


def test_every_class_is_sampled():
    assert {type(o) for o in samples().values()} == set(CLASSES)


def test_pickled_objects_keep_working():
    s = samples()
    f = pickle.loads(pickle.dumps(s["Filemon"]))
    assert np.array_equal(f.branch_map(*VP, 40, 30), s["Filemon"].branch_map(*VP, 40, 30))
    m = pickle.loads(pickle.dumps(s["SolutionMap"]))
    for col in SolutionMap.columns:
        a, b = getattr(m, col), getattr(s["SolutionMap"], col)
        assert a.dtype == b.dtype and a.tobytes() == b.tobytes(), col
        assert not a.flags["WRITEABLE"]
    assert m.best_pivots(3) == s["SolutionMap"].best_pivots(3)
    assert m.limits == DesignLimits(25.0, 8.0, "any") and m.task == s["Task"]
    sfb = pickle.loads(pickle.dumps(s["SynthesizedFourBar"]))
    assert sfb.figures == s["SynthesizedFourBar"].figures and sfb.travel == s["SynthesizedFourBar"].travel


def _branch_share(f):
    return float(f.branch_map(*VP, 64, 64).mean())


def test_objects_go_to_worker_processes():
    """What the pickling is for: tasks, constructions and maps in a pool.
    (Spawned, not forked: a fork does not copy the parent's worker threads.)"""
    t = Task(POSES)
    fs = [t.filemon(c) for c in (C0, (3.0, -2.0), (5.0, 1.0))]
    with ProcessPoolExecutor(max_workers=2, mp_context=multiprocessing.get_context("spawn")) as pool:
        shares = list(pool.map(_branch_share, fs))
    assert shares == [_branch_share(f) for f in fs]


def test_maps_are_compared_by_value():
    f = Task(POSES).filemon(C0)
    a = f.solution_map(*VP, 16, 16)
    assert a == f.solution_map(*VP, 16, 16)  # NaN columns compare equal by their bits
    assert a != f.solution_map(*VP, 16, 16, min_transmission_deg=40)
    assert a != f.solution_map(*VP, 16, 17)
    assert a != "a map"


# ---------------------------------------------------------------------------
# The naming rule


def _kind(cls, name):
    """"property" for a value read without a call, "method" for a callable."""
    attr = inspect.getattr_static(cls, name)
    kind = type(attr).__name__
    if kind in ("getset_descriptor", "member_descriptor", "property", "_tuplegetter"):
        return "property"
    if kind in ("method_descriptor", "builtin_function_or_method", "staticmethod", "classmethod", "function"):
        return "method"
    if isinstance(attr, list):
        return "class attribute"
    raise AssertionError((cls, name, kind))


#: Properties of each class: values held or derived without arguments, that cannot fail.
PROPERTIES = {
    Grid: "xmin xmax ymin ymax nx ny dx dy extent shape size",
    Conic: "coefficients kind center axis_angle asymptotes",
    Cubic: "coefficients degree is_circular asymptotic_directions",
    CoincidencePoint: "pair center circle",
    CurveDyad: "center circle dyad beta2 branch order direction",
    FourBar: "ground crank coupler rocker lengths input_pivot output_pivot ground_angle link_ratio grashof "
             "input_turns_fully input_range dead_positions grashof_margin",
    burmester.Configuration: "theta2 theta3 theta4 mode toggle transmission_angle coupler_rocker_angle",
    LinkageFigures: "lengths grashof input_full modes direction one_circuit min_transmission_deg link_ratio "
                    "branch_free feasible grashof_margin",
    Pole: "pair point direction at_infinity",
    Task: "poses rotations scale span poles",
    Filemon: "task driven_center driven_circle fixed_pivot_images all_defective lines all_lines sectors conics "
             "extreme_poses middle_pose",
    SynthesizedFourBar: "fourbar size size_ratio driving driven input_angles modes coupler_point "
                        "coupler_angle_offset figures branch_free travel travel_stops",
    DesignLimits: "min_transmission_deg max_link_ratio input max_size_ratio max_link_length min_grashof_margin",
    Pivot: "center index linkage figures margin size_ratio score ranked_by",
    SolutionMap: "valid branch_free grashof input_full direction one_circuit min_transmission_rad link_ratio "
                 "size_ratio acceptable grid extent shape varying fixed_dyad task limits fixed_kind",
    burmester.PivotAtlas: "branch_free_fraction shape rank_by",
    burmester.AtlasPair: "driven driving min_transmission_deg link_ratio margin n_acceptable driven_index driving_index "
                         "score size_ratio",
    burmester.Space: "region pivot_box pivot_polygon obstacles link_width envelope travel_samples",
    burmester.Design: "linkage figures score size_ratio ranked_by driving_pivot driven_pivot found_by coarse refined "
                      "coarse_score evaluations drive",
    burmester.NearMiss: "linkage figures size_ratio misses shortfall",
    burmester.DesignReport: "task designs near_misses rejections main_rejection census limits space rank_by "
                            "min_separation search_box coarse_candidates coarse_acceptable evaluations "
                            "undriven motor swing_margin_deg max_time_ratio",
    burmester.PairMap: "valid branch_free grashof input_full direction one_circuit min_transmission_rad link_ratio "
                       "size_ratio acceptable grid extent shape driving_dyads driven_dyads task limits",
    burmester.Pair: "driving driven index linkage figures margin size_ratio score ranked_by",
    burmester.SixBar: "drive motion drive_mode motion_mode attachment_angle coupler_point coupler_angle_offset "
                      "drive_pivot lengths attachment_side link_ratio size drive_grashof crank_turns_fully "
                      "limit_positions swing stroke_angle time_ratio min_transmission_deg dead_positions",
    burmester.Drive: "sixbar linkage task drive_pivot attachment pose_crank_angles stroke_start direction "
                     "acceptable index margin score ranked_by limits swing_margin_deg min_transmission_deg "
                     "drive_transmission_deg motion_transmission_deg time_ratio link_ratio size_ratio swing stroke",
    burmester.DriveMap: "valid min_transmission_rad drive_transmission_rad time_ratio link_ratio size_ratio "
                        "acceptable grid extent shape linkage attachment attachment_ends swing "
                        "motion_transmission_deg limits swing_margin_deg max_time_ratio",
    burmester.SliderFilemon: "task circle guide normal directions all_defective lines all_lines sectors conics "
                             "extreme_poses middle_pose",
    burmester.Actuator: "linkage link ground point pose_lengths monotone extends turning_points min_length "
                        "max_length stroke stroke_ratio min_transmission_deg worst_angle link_ratio size_ratio "
                        "acceptable index margin score ranked_by max_stroke_ratio limits",
    burmester.ActuatorMap: "valid monotone extends min_transmission_rad stroke_ratio stroke closed_length "
                           "link_ratio size_ratio acceptable grid extent shape linkage link point "
                           "point_at_poses limits max_stroke_ratio samples",
}

# Issue 27 (sdes31): a design's linear actuator and the strut's clearance.
PROPERTIES[burmester.Design] += " actuator"
PROPERTIES[burmester.DesignReport] += " actuator unplaced"
PROPERTIES[burmester.Actuator] += " min_clearance clearance_angle clear"

# Issue 27 (clr32): the strut's diameter and least gap, the map's clearance column.
PROPERTIES[burmester.Actuator] += " actuator_width min_gap link_width"
PROPERTIES[burmester.ActuatorMap] += " clearance actuator_width min_gap"
# The design's strut stage has its own size bound (act38).
PROPERTIES[burmester.DesignReport] += " actuator_max_size_ratio"

# Issue 27 (ssynth27): the slider records.
PROPERTIES[burmester.SliderDyad] = "circle guide normal"
PROPERTIES[burmester.InvertedSlider] = "swivel direction"

#: Methods of each class: they take arguments, can fail, or do real work.
METHODS = {
    Grid: "cell_centers point nearest",
    Conic: "evaluate evaluate_many side distance polylines",
    Cubic: "evaluate gradient distance intersect_line polylines",
    FourBar: "from_pivots solve configuration solve_many transmission_angle joints coupler_point coupler_path",
    Task: "rotation image_poles image_poles_in pole_circle image_pole_circle pole_triangle_angles displace "
          "circle_point center_point circle_points center_points dyad crank_angles filemon four_bar "
          "driven_solution_map pair_map line_to_conic center_point_curve circle_point_curve coincidence_points "
          "curve_dyad curve_dyads order_arcs branch_free_arcs curve_branch burmester_points burmester_curves burmester_four_bars",
    Filemon: "line_conic is_branch_free classify classify_circle_point circle_signs conic_values four_bar "
             "branch_map margin_map margin solution_map",
    SynthesizedFourBar: "travel_angles pose_at score drive_map drive classic_drive drive_search best_drive "
                        "actuator_map actuator",
    SolutionMap: "point linkage margin best_pivots pareto_front slider_crank",
    burmester.PivotAtlas: "best_pairs",
    burmester.AtlasPair: "linkage",
    burmester.Space: "contains_pivot search_box",
    burmester.PairMap: "linkage margins best_pairs pareto_front",
    burmester.SixBar: "solve transmission_angles toggle joints pose_at coupler_path crank_angles crank_angles_for_input",
    burmester.Drive: "turn_angles pose_at",
    burmester.DriveMap: "point drive best_drives pareto_front classic_drive",
    burmester.SliderFilemon: "line_conic classify classify_circle_point circle_signs conic_values branch_map "
    "solution_map",
    burmester.Actuator: "at travel",
    burmester.ActuatorMap: "ground placement best_placements pareto_front",
}

# Slider linkages (issue 27).
PROPERTIES[burmester.SliderCrank] = (
    "crank coupler pivot guide guide_normal foot offset link_ratio turns_fully input_range dead_positions "
    "collinear_positions")
PROPERTIES[burmester.SliderConfiguration] = "theta2 theta3 slider mode toggle transmission_angle"
PROPERTIES[burmester.SynthesizedSliderCrank] = (
    "linkage driving driven input_angles modes slider_positions coupler_point coupler_angle_offset direction "
    "one_circuit min_transmission_deg stroke_used size size_ratio branch_free feasible order travel travel_stops")
METHODS[burmester.SliderCrank] = "guide_point solve joints coupler_point coupler_path limits stroke"
METHODS[burmester.SynthesizedSliderCrank] = "travel_angles pose_at"
METHODS[Task] += " slider_crank"
# Issue 27 (ssynth27): slider dyads and inverted sliders.
METHODS[Task] += " slider_circle slider_dyads slider_dyad inverted inverted_sliders inverted_slider"
METHODS[burmester.InvertedSlider] = "body_line_at"
# The inverted slider-crank (issue 27, inv31).
PROPERTIES[burmester.InvertedSliderCrank] = (
    "crank pivot swivel offset ground turns_fully input_range dead_positions stroke")
PROPERTIES[burmester.InvertedConfiguration] = "theta2 theta3 slot mode toggle transmission_angle"
PROPERTIES[burmester.SynthesizedInvertedSliderCrank] = (
    "linkage driving driven input_angles modes slot_positions coupler_point coupler_angle_offset direction "
    "one_circuit min_transmission_deg stroke_used swing_used_deg size size_ratio branch_free feasible order "
    "travel travel_stops")
METHODS[burmester.InvertedSliderCrank] = "solve joints coupler_point coupler_path slot_limits swing time_ratio"
METHODS[burmester.SynthesizedInvertedSliderCrank] = "travel_angles pose_at"
PROPERTIES[burmester.SliderPivot] = "center index linkage margin size_ratio score ranked_by"  # srank32
METHODS[SolutionMap] += " best_slider_pivots slider_pareto_front"
METHODS[Task] += " inverted_slider_crank"

# The one-call design of slider-cranks (issue 27, sdes32).
PROPERTIES[burmester.Design] += " driven_kind"
PROPERTIES[burmester.NearMiss] += " driven_kind"

#: Methods without arguments, and why each is a method.
NO_ARGUMENT_METHODS = {
    (Grid, "cell_centers"): "does work: allocates two arrays",
    **{(Task, name): "fails for four or five poses"
       for name in ("image_poles", "pole_circle", "image_pole_circle", "pole_triangle_angles")},
    **{(Task, name): "fails for three or five poses"
       for name in ("center_point_curve", "circle_point_curve", "coincidence_points")},
    (Task, "burmester_points"): "fails for three or four poses; does work",
    (Task, "burmester_curves"): "fails for three or four poses",
    (Task, "burmester_four_bars"): "fails for three or four poses; does work",
    (SolutionMap, "pareto_front"): "does work: scans every sample and builds each linkage on the front",
    (burmester.PairMap, "margins"): "does work: a distance transform over every pair",
    (burmester.PairMap, "pareto_front"): "does work: scans every pair and builds each linkage on the front",
    (burmester.DriveMap, "pareto_front"): "does work: scans every sample and builds each drive on the front",
    (burmester.ActuatorMap, "pareto_front"): "does work: scans every sample and places each actuator on the front",
}


# Issue 27 (ssynth27).
NO_ARGUMENT_METHODS[(Task, "slider_circle")] = "fails for four or five poses"
NO_ARGUMENT_METHODS[(Task, "inverted")] = "can fail (the inverted poses are checked as a task's); does work"
NO_ARGUMENT_METHODS[(SolutionMap, "slider_pareto_front")] = (  # srank32
    "fails for a map with a driven crank; does work: scans every sample and builds each slider-crank on the front")


def _public(cls):
    return {n for n in vars(cls) if not n.startswith("_")}


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_naming_rule(cls):
    props = set(PROPERTIES.get(cls, "").split())
    methods = set(METHODS.get(cls, "").split())
    for name in props:
        assert _kind(cls, name) == "property", (cls.__name__, name)
    for name in methods:
        assert _kind(cls, name) == "method", (cls.__name__, name)
    attrs = {"columns", "grashof_names"} if cls in (SolutionMap, burmester.PairMap) else set()
    if cls in (burmester.DriveMap, burmester.ActuatorMap):
        attrs = {"columns"}
    for name in attrs:
        assert _kind(cls, name) == "class attribute"
    # Nothing public is left unclassified.
    assert _public(cls) == props | methods | attrs, cls.__name__
    # A method without arguments has a reason to be one.
    for name in methods:
        fn = getattr(cls, name)
        native = hasattr(fn, "__text_signature__")
        sig = inspect.signature(fn) if not native or fn.__text_signature__ else None
        if sig is not None:
            params = [p for p in sig.parameters.values() if p.name != "self"]
            if not params:
                assert (cls, name) in NO_ARGUMENT_METHODS, (cls.__name__, name)


def test_properties_never_fail():
    """Every property of every sample (tasks of 3, 4 and 5 poses included) reads without an error."""
    for name, obj in samples().items():
        for prop in PROPERTIES[type(obj)].split():
            getattr(obj, prop)


def test_old_names_are_gone():
    f = Task(POSES).filemon(C0)
    assert not hasattr(f, "circle_point")  # now driven_circle
    assert not hasattr(f.four_bar(FREE_PIVOT), "is_branch_free")  # now the property branch_free
    assert not hasattr(SolutionMap, "min_transmission")  # now min_transmission_rad
    fb = FourBar(ground=4, crank=1, coupler=3, rocker=3)
    assert fb.grashof == "crank-rocker" and not callable(fb.grashof)
    assert isinstance(Task(POSES).poles, list)


# ---------------------------------------------------------------------------
# Errors with fields


def _raised(fn):
    with pytest.raises(burmester.BurmesterError) as e:
        fn()
    return e.value


def test_every_error_carries_its_cause_and_fields():
    t = Task(POSES)
    fb = FourBar(ground=3, crank=2, coupler=1.5, rocker=1)
    pc = t.pole_circle()
    on_circle = (pc["center"][0] + pc["radius"], pc["center"][1])
    rot = [(math.cos(a), math.sin(a), a) for a in (0.0, 1.0, 2.0)]  # rotations about the origin
    cases = [
        # (call, class, cause, fields)
        (lambda: FourBar(ground=math.nan, crank=1, coupler=1, rocker=1), InvalidInputError, "not_finite",
         {"name": "ground length"}),
        (lambda: FourBar(ground=1, crank=0, coupler=1, rocker=1), InvalidInputError, "not_positive",
         {"name": "crank length", "value": 0.0}),
        (lambda: DesignLimits(120), InvalidInputError, "outside_range",
         {"name": "min_transmission_deg", "value": 120.0, "min": 0.0, "max": 90.0, "unit": "degrees"}),
        (lambda: DesignLimits(30, 0.5), InvalidInputError, "outside_range",
         {"name": "max_link_ratio", "value": 0.5, "min": 1.0, "max": math.inf}),
        (lambda: Task([(1e101, 0, 0), (2, 0.5, 0.4), (3, 2, 1.1)]), InvalidInputError, "too_large",
         {"name": "pose 1 x", "value": 1e101, "limit": 1e100}),
        (lambda: Task([(0, 0, 0), (1e-102, 0, 0.4), (0, 1e-102, 1.1)]), InvalidInputError, "too_small", {}),
        (lambda: t.four_bar(FREE_PIVOT, C0).travel_angles(1), InvalidInputError, "count_out_of_range",
         {"value": 1, "min": 2}),
        (lambda: fb.solve(0.1, "sideways"), InvalidInputError, "unknown_name",
         {"what": "assembly mode", "found": "sideways"}),
        (lambda: Task(POSES[:2]), InvalidInputError, "pose_count", {"found": 2, "min": 3, "max": 5}),
        (lambda: Task(FOUR).filemon(C0), InvalidInputError, "needs_poses", {"required": 3, "found": 4}),
        (lambda: t.displace((0, 0), 1, 4), InvalidInputError, "pose_index", {"index": 4, "count": 3}),
        (lambda: Grid(0, 1, 0, 1, 0, 5), InvalidInputError, "grid_size", {"nx": 0, "ny": 5, "max": 2**32}),
        (lambda: Grid(1, 0, 0, 1, 5, 5), InvalidInputError, "viewport",
         {"xmin": 1.0, "xmax": 0.0, "ymin": 0.0, "ymax": 1.0}),
        (lambda: t.line_to_conic((0, 0), (0, 0)), InvalidInputError, "zero_direction", {"x": 0.0, "y": 0.0}),
        (lambda: Conic(0, 0, 0, 0, 0, 1), InvalidInputError, "conic_coefficients", {}),
        (lambda: t.filemon(C0).solution_map(*VP, 4, 4, obstacles=[[(0, 0), (1, 1)]]), InvalidInputError,
         "polygon", {"name": "obstacle 1", "vertices": 2}),
        (lambda: FourBar(ground=10, crank=1, coupler=2, rocker=3), AssemblyError, "never_closes",
         {"longest": 10.0, "others": 6.0}),
        (lambda: fb.solve(math.pi), AssemblyError, "out_of_reach",
         {"theta2": math.pi, "distance": 5.0, "min_reach": 0.5, "max_reach": 2.5}),
        (lambda: FourBar(ground=1, crank=1, coupler=2, rocker=2).solve(0.0), AssemblyError, "indeterminate",
         {"theta2": 0.0}),
        (lambda: Task([(0, 0, 0.3), (0, 0, 0.3), (2, 2, 1.0)]), DegenerateError, "coincident_poses",
         {"i": 1, "j": 2}),
        (lambda: Task([(0, 0, 0.3), (1, 0, 0.3), (2, 2, 1.0)]).pole_circle(), DegenerateError,
         "pure_translation", {"i": 1, "j": 2}),
        (lambda: Task([(0, 0, 0.3), (1, 0, 0.3), (2, 2, 0.3)]), DegenerateError, "all_translations", {}),
        (lambda: Task(rot), DegenerateError, "coincident_poles", {}),
        (lambda: t.circle_point(on_circle), DegenerateError, "at_infinity",
         {"what": "circle point", "curve": "pole circle", "x": on_circle[0], "y": on_circle[1]}),
        (lambda: t.circle_point(t.poles[0].point), DegenerateError, "undefined",
         {"what": "circle point", "at": "the pole P12"}),
        # Raised by the binding itself, with a cause too.
        (lambda: FourBar(ground=10**400, crank=1, coupler=1, rocker=1), InvalidInputError, "too_large", {}),
        (lambda: t.circle_points(np.zeros((2, 3))), InvalidInputError, "shape", {}),
        (lambda: Grid(*VP, 4, 4).point(4, 0), InvalidInputError, "grid_index", {}),
        (lambda: Task([(0, 0, 0), (1, 2), (3, 2, 1.1)]), InvalidInputError, "pose_shape", {}),
    ]
    for fn, cls, cause, fields in cases:
        e = _raised(fn)
        assert type(e) is cls, (cause, e)
        assert e.cause == cause, (cause, e.cause, str(e))
        for name, want in fields.items():
            got = getattr(e, name)
            if isinstance(want, float) and math.isfinite(want):
                assert isinstance(got, float) and got == pytest.approx(want, rel=1e-12), (cause, name, got)
            else:
                assert got == want, (cause, name, got)
        # Fields survive pickling (exceptions go back from worker processes too).
        back = pickle.loads(pickle.dumps(e))
        assert type(back) is cls and str(back) == str(e) and back.cause == cause
        for name in fields:
            assert getattr(back, name) == getattr(e, name)


def test_an_answer_at_infinity_says_where():
    """The direction of an answer at infinity is the limit of the answers nearby."""
    t = Task(POSES)
    pc = t.pole_circle()
    cx, cy = pc["center"]
    for a in (0.3, 1.7, 4.0):
        p = (cx + pc["radius"] * math.cos(a), cy + pc["radius"] * math.sin(a))
        e = _raised(lambda: t.circle_point(p))
        d = (e.dir_x, e.dir_y)
        assert math.hypot(*d) == pytest.approx(1.0)
        # Just off the circle, the circle point is far away along +-d.
        n = (math.cos(a), math.sin(a))
        q = t.circle_point((p[0] + 1e-7 * n[0], p[1] + 1e-7 * n[1]))
        far = (q[0] - p[0], q[1] - p[1])
        r = math.hypot(*far)
        assert r > 1e3
        assert abs(far[0] * d[0] + far[1] * d[1]) / r == pytest.approx(1.0, abs=1e-3)


# ---------------------------------------------------------------------------
# Tasks of four and five poses


def test_tasks_of_four_and_five_poses():
    for poses in (FOUR, FIVE):
        t = Task(poses)
        n = len(poses)
        assert len(t) == n and t.poses == [tuple(map(float, p)) for p in poses]
        pairs = [(i, j) for i in range(1, n + 1) for j in range(i + 1, n + 1)]
        assert [p.pair for p in t.poles] == pairs
        assert len(t.rotations) == len(pairs)
        for (i, j), rot, pole in zip(pairs, t.rotations, t.poles):
            assert rot == pytest.approx(t.rotation(i, j))
            if pole.at_infinity:
                assert pole.point is None and rot == pytest.approx(0.0)
            else:
                # A finite pole is the fixed point of its displacement.
                assert pole.direction is None
                assert t.displace(pole.point, i, j) == pytest.approx(pole.point, abs=1e-9)
        assert t.scale > 0
        assert t == Task(poses) and t != Task(POSES)


def test_a_pure_translation_has_its_pole_at_infinity():
    t = Task(FOUR)
    p34 = t.poles[-1]
    assert p34.pair == (3, 4) and p34.at_infinity and p34.point is None
    # Perpendicular to the translation (1, 0), a unit vector.
    dx, dy = p34.direction
    assert math.hypot(dx, dy) == pytest.approx(1.0) and dx == pytest.approx(0.0)
    assert [p.at_infinity for p in t.poles] == [False] * 5 + [True]
    assert "direction=" in repr(p34)
    # Three poses take it too; only the pole triangle needs it finite.
    three = Task(FOUR[1:])
    assert three.poles[-1].at_infinity
    with pytest.raises(DegenerateError) as e:
        three.pole_circle()
    assert (e.value.cause, e.value.i, e.value.j) == ("pure_translation", 2, 3)


@pytest.mark.parametrize("poses", [FOUR, FIVE], ids=["4 poses", "5 poses"])
def test_three_pose_methods_say_they_need_three(poses):
    t = Task(poses)
    calls = {
        "image_poles": lambda: t.image_poles(),
        "image_poles_in": lambda: t.image_poles_in(1),
        "pole_circle": lambda: t.pole_circle(),
        "image_pole_circle": lambda: t.image_pole_circle(),
        "pole_triangle_angles": lambda: t.pole_triangle_angles(),
        "filemon": lambda: t.filemon(C0),
        "driven_solution_map": lambda: t.driven_solution_map((1.0, 1.0), *VP, 4, 4),
        "line_to_conic": lambda: t.line_to_conic((0.0, 0.0), (1.0, 0.0)),
    }
    if len(poses) == 5:
        # Three or four poses (the closed-form maps, or the center-point curve).
        calls.update({
            "circle_point": lambda: t.circle_point((1.0, 1.0)),
            "center_point": lambda: t.center_point((1.0, 1.0)),
            "circle_points": lambda: t.circle_points([[1.0, 1.0]]),
            "center_points": lambda: t.center_points([[1.0, 1.0]]),
        })
    for name, fn in calls.items():
        with pytest.raises(InvalidInputError, match="needs a task of 3 poses") as e:
            fn()
        assert (e.value.cause, e.value.required, e.value.found) == ("needs_poses", 3, len(poses)), name


def test_pole_records():
    p = Pole((1, 2), (0.5, -1.0))
    assert (p.pair, p.point, p.direction, p.at_infinity) == ((1, 2), (0.5, -1.0), None, False)
    q = Pole((2, 4), direction=(0.0, 1.0))
    assert q.at_infinity and q.point is None and q.direction == (0.0, 1.0)
    assert p == Pole((1, 2), (0.5, -1.0)) and p != q
    assert eval(repr(p), {"Pole": Pole}) == p and eval(repr(q), {"Pole": Pole}) == q
    with pytest.raises(TypeError, match="either a point or a direction"):
        Pole((1, 2))
    with pytest.raises(TypeError, match="either a point or a direction"):
        Pole((1, 2), (0.0, 0.0), (1.0, 0.0))
    for pair in ((0, 1), (2, 2), (3, 2), (1, 6)):
        with pytest.raises(InvalidInputError, match="1 <= i < j") as e:
            Pole(pair, (0.0, 0.0))
        assert e.value.cause == "pose_index"
    with pytest.raises(InvalidInputError):
        Pole((1, 2), direction=(0.0, 0.0))
    with pytest.raises(InvalidInputError):
        Pole((1, 2), (math.nan, 0.0))


# ---------------------------------------------------------------------------
# Grid, DesignLimits, Pivot


def test_grid():
    g = Grid(-8.0, 8.0, -6.0, 6.0, 40, 30)
    assert (g.xmin, g.xmax, g.ymin, g.ymax, g.nx, g.ny) == (-8.0, 8.0, -6.0, 6.0, 40, 30)
    assert g.extent == (-8.0, 8.0, -6.0, 6.0) and g.shape == (30, 40) and g.size == 1200
    assert (g.dx, g.dy) == (0.4, 0.4)
    xs, ys = g.cell_centers()
    assert xs.shape == (40,) and ys.shape == (30,)
    assert xs[0] == -8.0 + 0.5 * 0.4 and ys[-1] == pytest.approx(6.0 - 0.2)
    assert g.point(3, 5) == (xs[5], ys[3])
    assert g.nearest(g.point(3, 5)) == (3, 5)
    assert g.nearest((100.0, -100.0)) == (0, 39)  # clamped
    assert g == Grid(-8, 8, -6, 6, 40, 30) and g != Grid(-8, 8, -6, 6, 40, 31)
    assert eval(repr(g), {"Grid": Grid}) == g
    with pytest.raises(InvalidInputError):
        g.point(30, 0)
    with pytest.raises(InvalidInputError):
        g.nearest((math.nan, 0.0))
    # The samples are those of every map.
    f = Task(POSES).filemon(C0)
    m = f.branch_map(g)
    for j in range(0, 30, 7):
        for i in range(0, 40, 9):
            assert m[j, i] == f.is_branch_free(g.point(j, i))


def test_design_limits():
    d = DesignLimits()
    assert (d.min_transmission_deg, d.max_link_ratio, d.input) == (30.0, 10.0, "any")
    assert repr(d) == "DesignLimits(min_transmission_deg=30.0, max_link_ratio=10.0, input='any')"
    e = DesignLimits(min_transmission_deg=42.5, max_link_ratio=math.inf, input="Crank")
    assert (e.min_transmission_deg, e.max_link_ratio, e.input) == (42.5, math.inf, "crank")
    assert eval(repr(e), {"DesignLimits": DesignLimits, "inf": math.inf}) == e
    assert DesignLimits(30, 10, "any") == d != e
    for bad in (dict(min_transmission_deg=-1), dict(min_transmission_deg=90.5), dict(max_link_ratio=0.99),
                dict(min_transmission_deg=math.nan), dict(max_link_ratio=math.nan)):
        with pytest.raises(InvalidInputError):
            DesignLimits(**bad)
    with pytest.raises(InvalidInputError, match="input requirement") as err:
        DesignLimits(input="motor")
    assert err.value.cause == "unknown_name"


def test_pivot_records_are_typed_and_immutable():
    f = Task(POSES).filemon(C0)
    m = f.solution_map(Grid(*VP, 80, 80))
    best = m.best_pivots(3)
    assert best and all(type(p) is Pivot for p in best)
    p = best[0]
    j, i = p.index
    assert isinstance(j, int) and isinstance(i, int) and p.center == m.point(j, i)
    assert p.linkage == m.linkage(j, i) and p.figures == p.linkage.figures
    assert p.margin == pytest.approx(m.margin(j, i)) and p.ranked_by == "balanced"
    assert p.size_ratio == p.linkage.size / m.task.span and p.score > 0
    for name in ("center", "index", "linkage", "figures", "margin", "size_ratio", "score", "ranked_by"):
        with pytest.raises(AttributeError):
            setattr(p, name, None)
    with pytest.raises(TypeError):
        p["center"]  # not a dict any more
    rebuilt = Pivot(p.center, p.index, p.linkage, p.margin, p.score, p.ranked_by)
    assert rebuilt == p
    assert rebuilt != Pivot(p.center, p.index, p.linkage, p.margin, p.score, "margin")
    assert f"size_ratio={p.size_ratio:.3f} by balanced" in repr(p)


def test_figures_name_their_units():
    sfb = Task(POSES).filemon(C0).four_bar(FREE_PIVOT)
    fig = sfb.figures
    assert 0 <= fig.min_transmission_deg <= 90
    assert fig.lengths == sfb.fourbar.lengths and fig.grashof == sfb.fourbar.grashof
    assert fig.input_full == sfb.fourbar.input_turns_fully
    assert fig.modes == sfb.modes and fig.branch_free == sfb.branch_free
    # The travel: its stops are the poses' input angles, unwrapped along its direction.
    start, span = sfb.travel
    stops = sfb.travel_stops
    assert stops[0] == start == sfb.input_angles[0]
    assert math.copysign(1, span) == {"ccw": 1, "cw": -1}[fig.direction]
    for stop, theta in zip(stops, sfb.input_angles):
        assert math.remainder(stop - theta, 2 * math.pi) == pytest.approx(0.0, abs=1e-12)
    assert stops[-1] == pytest.approx(start + span)
    angles = sfb.travel_angles(9)
    assert angles.shape == (9,) and angles[0] == start and angles[-1] == pytest.approx(start + span)
    # The minimum transmission over the travel is at most the angle at any point of it.
    fb = sfb.fourbar
    mus = [math.degrees(fb.transmission_angle(float(t), fig.modes[0])) for t in sfb.travel_angles(257)]
    assert fig.min_transmission_deg <= min(mus) + 1e-9
    assert fig.min_transmission_deg == pytest.approx(min(mus), abs=0.1)
