"""Accuracy of the samples (``t_eval``, from the dense output) against that of the steps, for
the explicit pairs: x'' = -x over [0, 20], x = cos t, ``atol = 1e-3 rtol``, 2001 samples.

The anchor is the closed form; the figure is the ratio of the largest error at the samples to
the largest error at the method's own steps (1: the samples are as accurate as the steps).
Run::

    PYTHONPATH=src python benchmarks/dense_vs_steps.py      # a few seconds
"""

import numpy as np

from rigidmech import ode


def oscillator(t, y):
    return np.array([y[1], -y[0]])


def main():
    te = np.linspace(0.0, 20.0, 2001)
    print(f"{'method':>8} {'rtol':>7} {'at steps':>9} {'at samples':>10} {'ratio':>6}")
    for method in ("dop853", "dopri5", "bs32"):
        for rtol in (1e-6, 1e-8, 1e-10):
            kw = dict(method=method, rtol=rtol, atol=1e-3 * rtol)
            steps = ode.solve(oscillator, (0.0, 20.0), [1.0, 0.0], **kw)
            samples = ode.solve(oscillator, (0.0, 20.0), [1.0, 0.0], t_eval=te, **kw)
            ea = np.abs(steps.y[0] - np.cos(steps.t)).max()
            eb = np.abs(samples.y[0] - np.cos(samples.t)).max()
            print(f"{method:>8} {rtol:>7.0e} {ea:>9.2e} {eb:>10.2e} {eb / ea:>6.2f}")


if __name__ == "__main__":
    main()
