"""The Pareto chart keeps its labels apart (lesson 06's depth chart had two on top of each other)."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from teachraster.plotting.pareto import LABEL_SPOTS, plot_pareto, spread_labels  # noqa: E402


def test_labels_of_close_points_take_different_spots():
    rows = [
        {"variant": "linear unorm16", "bits": 16, "error": 2900.0},
        {"variant": "window unorm16", "bits": 16, "error": 2500.0},
        {"variant": "window float64", "bits": 53, "error": 0.0},
    ]
    fig, ax = plt.subplots(figsize=(9, 5))
    art = plot_pareto(ax, rows, "bits", logx=False)
    a, b = (art.labels[v].get_position() for v in ("linear unorm16", "window unorm16"))
    assert a != b  # the second label moved to another spot beside its point
    # a linear cost axis ends near the data (it ran to 3x the largest cost)
    assert ax.get_xlim()[1] < 53 * 1.7
    plt.close(fig)


def test_a_lone_label_keeps_the_first_spot():
    fig, ax = plt.subplots()
    ax.plot([1.0], [1.0])
    label = ax.annotate("alone", (1.0, 1.0), textcoords="offset points", xytext=(0, 0))
    spread_labels(ax, [label])
    sx, sy = LABEL_SPOTS[0]
    x, y = label.get_position()
    assert x * sx > 0 and y * sy > 0  # up and to the right
    plt.close(fig)


def test_a_front_point_is_drawn_above_the_points_it_beats():
    # lesson 06's edge chart: the one-point front sat under grey points at the same place
    rows = [
        {"variant": "front", "cycles": 3.0, "error": 0.0},
        {"variant": "worse", "cycles": 3.0, "error": 1.0},
        {"variant": "dearer", "cycles": 27.0, "error": 0.0},
    ]
    fig, ax = plt.subplots()
    art = plot_pareto(ax, rows, "cycles", logx=False)
    assert art.points["front"].get_zorder() > art.points["dearer"].get_zorder()
    assert [r["variant"] for r in art.front] == ["front"]
    plt.close(fig)


def test_no_error_tick_is_labelled_at_or_below_the_exact_floor():
    """Review r3 06-4: on a log axis the "0 (exact)" floor stands for zero; a tick labelled 20
    under a floor drawn at 45 read as fewer wrong pixels than exact."""
    from matplotlib.ticker import FormatStrFormatter, LogLocator

    from teachraster.plotting.pareto import floor_ticks

    rows = [
        {"variant": "exact", "bits": 64, "error": 0.0},
        {"variant": "coarse", "bits": 16, "error": 450.0},
        {"variant": "fine", "bits": 24, "error": 3000.0},
    ]
    fig, ax = plt.subplots(figsize=(9, 5))
    art = plot_pareto(ax, rows, "bits", logx=False)
    ax.yaxis.set_major_locator(LogLocator(subs=(1, 2, 5)))
    floor_ticks(ax, art.floor, FormatStrFormatter("%g"))
    fig.canvas.draw()
    labelled = [float(t.get_text()) for t in ax.get_yticklabels() if t.get_text()]
    assert labelled and min(labelled) > 2 * art.floor
    # review r6, 06-2: no major (decade) tick left bare between the floor and its first label
    lo, hi = ax.get_ylim()
    shown = [y for y in ax.yaxis.get_majorticklocs() if lo <= y <= hi]
    assert shown and min(shown) > 2 * art.floor
    plt.close(fig)


def test_no_bare_decade_tick_above_the_floor_with_the_default_locator():
    """Review r6, 06-2: with the floor at 0.7, the decade 10^0 sat above it unlabelled."""
    rows = [
        {"variant": "exact", "cycles": 6, "error": 0.0},
        {"variant": "a", "cycles": 3, "error": 7.0},
        {"variant": "b", "cycles": 2, "error": 200.0},
    ]
    fig, ax = plt.subplots(figsize=(9, 5))
    art = plot_pareto(ax, rows, "cycles")
    fig.canvas.draw()
    lo, hi = ax.get_ylim()
    locs, labels = ax.yaxis.get_majorticklocs(), ax.get_yticklabels()
    ticks = [(y, t.get_text()) for y, t in zip(locs, labels) if lo <= y <= hi]
    assert art.floor < 1.0 < 2 * art.floor and ticks
    assert all(text for _, text in ticks), ticks
    plt.close(fig)


def test_the_floor_keeps_a_log_axis_from_labelling_every_minor_tick():
    """Wrapping the formatters must keep the log formatter's choice of labelled minor ticks
    (a first version labelled 2x10^1 ... 9x10^2 over three decades, one on top of another)."""
    rows = [
        {"variant": "exact", "cycles": 3, "error": 0.0},
        {"variant": "a", "cycles": 27, "error": 50.0},
        {"variant": "b", "cycles": 3, "error": 470.0},
    ]
    fig, ax = plt.subplots(figsize=(9, 5))
    plot_pareto(ax, rows, "cycles", logx=False)
    fig.canvas.draw()
    labelled = [t for t in ax.get_yticklabels(minor=True) if t.get_text()]
    assert len(labelled) <= 2
    plt.close(fig)


#: Lesson 06's DivideCostExplorer at divide 1 (review r12): seven points on a short diagonal.
CROWDED = [("affine", 1, 210), ("N=32", 1.3, 70), ("N=16", 1.6, 50), ("N=8", 2.2, 24),
           ("N=4", 3.5, 14), ("N=2", 6, 5.7), ("perspective", 6, 0)]  # fmt: skip


def _drawn_boxes(fig, ax, art):
    """(label boxes, marker boxes, figure box) in display pixels after a full draw."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    labels = {k: lab.get_window_extent(renderer) for k, lab in art.labels.items()
              if lab.get_visible()}  # fmt: skip
    markers = {k: p.get_window_extent(renderer) for k, p in art.points.items()}
    return labels, markers, fig.bbox


def _assert_spread(fig, ax, art):
    labels, markers, figure = _drawn_boxes(fig, ax, art)
    names = list(labels)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            assert not labels[a].overlaps(labels[b]), (a, b)
        hit = [k for k, m in markers.items() if labels[a].overlaps(m)]
        assert not hit, (a, hit)
        box, frame = labels[a], ax.bbox
        assert frame.x0 <= box.x0 and box.x1 <= frame.x1, (a, "out of the Axes")
        assert frame.y0 <= box.y0 and box.y1 <= frame.y1, (a, "out of the Axes")
        assert figure.x0 <= box.x0 and box.x1 <= figure.x1, (a, "out of the figure")


def test_crowded_labels_keep_clear_of_each_other_the_points_and_the_edges():
    """Review r12 (lesson 06's DivideCostExplorer at divide 1): crowded points put "N=16"
    against N=8's point. No two labels overlap, none covers a point's marker, and every label
    stays inside the Axes (a first fix pushed a label of the edge-function chart out of them:
    the figure grew to 951 px)."""
    rows = [{"variant": n, "cost": c, "error": e} for n, c, e in CROWDED]
    fig, ax = plt.subplots(figsize=(5, 3.2), dpi=100)
    art = plot_pareto(ax, rows, "cost")
    _assert_spread(fig, ax, art)
    plt.close(fig)


def test_labels_are_placed_for_the_axes_the_figure_is_drawn_with():
    """A layout engine (the lessons' ``layout="constrained"``) moves the Axes only when the
    figure is drawn: labels placed for the Axes before it must be placed again, or one ends
    up outside them (and a figure saved tight grows: 951 px in lesson 06)."""
    rows = [{"variant": "affine", "cycles": 1, "error": 100.0},
            {"variant": "subdivided", "cycles": 2, "error": 10.0},
            {"variant": "perspective", "cycles": 10, "error": 0.0}]  # fmt: skip
    fig, ax = plt.subplots(figsize=(6, 3.2), dpi=100)
    art = plot_pareto(ax, rows, "cycles", logx=False)
    ax.set_position((0.3, 0.2, 0.35, 0.6))  # as a layout engine would, before drawing
    _assert_spread(fig, ax, art)
    plt.close(fig)


def test_a_label_the_caller_moved_stays_where_it_was_put():
    """Lesson 06's depth chart places its labels itself after plot_pareto: a draw must not
    spread them again."""
    rows = [{"variant": n, "cost": c, "error": e} for n, c, e in CROWDED]
    fig, ax = plt.subplots(figsize=(5, 3.2), dpi=100)
    art = plot_pareto(ax, rows, "cost")
    art.labels["N=8"].set_position((9, -4))
    fig.canvas.draw()
    assert art.labels["N=8"].get_position() == (9, -4)
    plt.close(fig)


@pytest.mark.parametrize("worst", [100.0, 0.1], ids=["floor 10", "floor 0.01"])
def test_a_floor_at_a_decade_sets_no_identical_limits(worst):
    """plot_pareto turned the error axis log after drawing the floor line, its only y value:
    with the floor at a decade (10 here; 0.01 in lesson 06's DivideCostExplorer, drawing its
    other error measure ahead) matplotlib's log autoscale of that one value gave equal limits
    and warned "Attempting to set identical low and high ylims" (pareto.py, line 88)."""
    import warnings

    rows = [{"variant": "exact", "c": 2.0, "error": 0.0}, {"variant": "rough", "c": 1.0,
                                                           "error": worst}]  # fmt: skip
    fig, ax = plt.subplots()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        art = plot_pareto(ax, rows, "c")
        fig.canvas.draw()
    assert art.floor == worst / 10 and ax.get_ylim() == pytest.approx((worst / 30, worst * 3))
    plt.close(fig)


def test_the_divide_cost_explorer_draws_its_other_measure_ahead_without_a_warning():
    """Where the warning was seen (tests/test_frames_ahead.py): the explorer's second figure,
    fresh, drawing the mean error, floor 0.01."""
    import warnings

    from widget_examples import _rows

    from teachraster.widgets.divide_cost import DivideCostExplorer

    ex = DivideCostExplorer(_rows(), backend="image")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            ex.divide.value = 10.0
            ex._ahead.step()  # the other measure at this price, on a figure of its own
        assert ex._elsewhere.art.floor == pytest.approx(0.01)
    finally:
        ex.close()


def test_a_less_accurate_cost_tie_on_the_step_line_is_drawn_hollow_over_it():
    """Review r22 06-8: at divide = 1, N=2 costs what perspective-correct costs and sits on the
    front's vertical step; filled grey under the vermillion line it read as on the front."""
    rows = [
        {"variant": "affine", "cycles": 1.0, "error": 200.0},
        {"variant": "N=4", "cycles": 3.5, "error": 15.0},
        {"variant": "N=2", "cycles": 6.0, "error": 6.0},
        {"variant": "perspective", "cycles": 6.0, "error": 0.0},
    ]
    for hollow in (True, False):
        fig, ax = plt.subplots()
        art = plot_pareto(ax, rows, "cycles", hollow_on_line=hollow)
        tie, cheap = art.points["N=2"], art.points["affine"]
        assert "N=2" not in [r["variant"] for r in art.front]
        if hollow:
            assert tie.get_markerfacecolor() == "white"
            assert tie.get_zorder() > art.front_line.get_zorder()
        else:
            assert tie.get_markerfacecolor() == tie.get_color()
        assert cheap.get_markerfacecolor() == cheap.get_color()  # on the front: filled
        plt.close(fig)


def test_an_accuracy_tie_that_costs_more_is_drawn_hollow_and_a_point_off_the_line_is_not():
    """Review r24 06-1: the ring's rule is the step line's, both ways: lesson 06's window
    float32 has window unorm24's wrong pixels at 32 bits against 24 (on the line across),
    so it is hollow; a point dearer and less accurate than every front point is not."""
    rows = [
        {"variant": "unorm16", "bits": 16, "error": 5000.0},
        {"variant": "unorm24", "bits": 24, "error": 464.0},
        {"variant": "float32", "bits": 32, "error": 464.0},
        {"variant": "worse", "bits": 48, "error": 1000.0},
        {"variant": "float64", "bits": 64, "error": 0.0},
    ]
    fig, ax = plt.subplots()
    art = plot_pareto(ax, rows, "bits", logx=False, hollow_on_line=True)
    assert [r["variant"] for r in art.front] == ["unorm16", "unorm24", "float64"]
    assert art.points["float32"].get_markerfacecolor() == "white"
    worse = art.points["worse"]
    assert worse.get_markerfacecolor() == worse.get_color()
    plt.close(fig)
