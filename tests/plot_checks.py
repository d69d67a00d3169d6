"""Checks of the plot conventions shared by the plot tests (Agg backend): no label cut."""

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.text import Text


def _hidden_tick_labels(fig):
    """The labels of ticks beyond the view limits: matplotlib keeps them but does not draw
    them."""
    hidden = set()
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            lo, hi = sorted(axis.get_view_interval())
            span = (hi - lo) * 1e-9
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                if not lo - span <= tick.get_loc() <= hi + span:
                    hidden |= {id(tick.label1), id(tick.label2)}
    return hidden


def texts_outside(fig):
    """The drawn texts whose window extent leaves the figure (a cut label), after a draw."""
    if not hasattr(fig.canvas, "get_renderer"):      # a Figure made without pyplot
        FigureCanvasAgg(fig)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    box = fig.bbox
    hidden = _hidden_tick_labels(fig)
    out = []
    for t in fig.findobj(Text):
        if not t.get_visible() or not t.get_text() or id(t) in hidden:
            continue
        e = t.get_window_extent(renderer)
        if e.x0 < box.x0 - 0.5 or e.y0 < box.y0 - 0.5 or e.x1 > box.x1 + 0.5 \
                or e.y1 > box.y1 + 0.5:
            out.append(t.get_text())
    return out
