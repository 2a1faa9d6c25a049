"""hexgait.GaussianProcess (src/adapt/gaussian_process.h) against scikit-learn's
GaussianProcessRegressor with the same fixed kernel, sigma^2 * Matern(nu=2.5), fitted on the
residuals y - prior mean: the same posterior mean and standard deviation to rounding.

Run by CTest (python_module). scikit-learn is Debian's python3-sklearn (scripts/deps.sh --test);
without it this file is skipped with that reason.
"""
import numpy as np
import pytest

import hexgait

sklearn_gp = pytest.importorskip(
    "sklearn.gaussian_process",
    reason="scikit-learn is not installed (Debian: python3-sklearn, scripts/deps.sh --test)")
kernels = pytest.importorskip("sklearn.gaussian_process.kernels")


def sklearn_predict(x, y, prior, x_test, prior_test, length_scale, signal_variance, noise):
    kernel = kernels.ConstantKernel(signal_variance, "fixed") * kernels.Matern(
        length_scale=length_scale, nu=2.5, length_scale_bounds="fixed")
    gp = sklearn_gp.GaussianProcessRegressor(kernel=kernel, alpha=noise, optimizer=None,
                                             normalize_y=False)
    gp.fit(x, y - prior)
    mean, std = gp.predict(x_test, return_std=True)
    return mean + prior_test, std


@pytest.mark.parametrize("length_scale,signal_variance,noise,dims",
                         [(0.4, 1.0, 0.001, 6), (0.4, 1.0, 0.001, 2), (0.15, 4.0, 0.05, 3),
                          (1.0, 0.5, 1e-6, 1)])
def test_same_posterior_as_scikit_learn(length_scale, signal_variance, noise, dims):
    rng = np.random.default_rng(29 + dims)
    x = rng.random((12, dims))
    prior = rng.uniform(0, 14, 12)        # the archive's distances at the tried elites
    y = prior * rng.uniform(0.1, 1.1, 12)  # what the damaged creature walked
    x_test = np.vstack([rng.random((40, dims)), x[:3], np.full((1, dims), 30.0)])
    prior_test = rng.uniform(0, 14, len(x_test))
    gp = hexgait.GaussianProcess(length_scale=length_scale, signal_variance=signal_variance,
                                 noise=noise)
    gp.fit(x, y, prior)
    assert gp.observations == 12
    mean, std = gp.predict(x_test, prior_test)
    want_mean, want_std = sklearn_predict(x, y, prior, x_test, prior_test, length_scale,
                                          signal_variance, noise)
    np.testing.assert_allclose(mean, want_mean, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(std, want_std, rtol=1e-7, atol=1e-7)
    # Far from every trial: the prior, with the signal's standard deviation.
    assert mean[-1] == pytest.approx(prior_test[-1], abs=1e-12)
    assert std[-1] == pytest.approx(np.sqrt(signal_variance), abs=1e-12)


def test_defaults_are_the_ite_codes_and_bad_input_is_a_value_error():
    gp = hexgait.GaussianProcess()
    mean, std = gp.predict(np.zeros((1, 6)), np.array([3.0]))
    assert mean[0] == 3.0 and std[0] == 1.0  # no data: the prior, sigma^2 = 1
    with pytest.raises(ValueError, match="length scale must be a positive number"):
        hexgait.GaussianProcess(length_scale=0)
    with pytest.raises(ValueError, match="not positive definite"):
        hexgait.GaussianProcess(noise=0).fit(np.zeros((2, 2)), np.array([1.0, 2.0]))
    with pytest.raises(ValueError, match="one value and one prior mean per point"):
        gp.fit(np.zeros((3, 2)), np.array([1.0, 2.0]))


@pytest.mark.parametrize("normalise", ["none", "best", "spread"])
def test_trial_and_errors_normalised_predictions_are_scikit_learns(normalise):
    # Each trial's prediction (made before it) is scikit-learn's posterior given the trials
    # before it, on distances divided by the archive's best ("best") or with the signal variance
    # set to the archive's variance ("spread"), in distance units.
    rng = np.random.default_rng(5)
    descriptors = rng.random((60, 3))
    prior = rng.uniform(1, 14, 60)
    damaged = prior * rng.uniform(0.05, 1.0, 60)
    out = hexgait.trial_and_error(descriptors, prior, damaged, normalise=normalise, stop=None,
                                  trials=6, length_scale=0.4)
    scale = prior.max() if normalise == "best" else 1.0
    variance = prior.var() if normalise == "spread" else 1.0
    trials = out["trials"]
    assert len(trials) == 6  # stop=None: no stop rule
    assert 0 <= out["stop_rule_trials"] <= 6
    for k in range(1, len(trials)):
        tried = [t["elite"] for t in trials[:k]]
        x, y = descriptors[tried], np.array([t["distance"] for t in trials[:k]])
        elite = trials[k]["elite"]
        mean, std = sklearn_predict(x, y / scale, prior[tried] / scale, descriptors[[elite]],
                                    prior[[elite]] / scale, 0.4, variance, 0.001)
        assert trials[k]["predicted_mean"] == pytest.approx(scale * mean[0], rel=1e-9, abs=1e-9)
        assert trials[k]["predicted_std"] == pytest.approx(scale * std[0], rel=1e-7, abs=1e-7)
    # A callable trial gives the same loop as the array of every elite's distance.
    again = hexgait.trial_and_error(descriptors, prior, lambda i: damaged[i], normalise=normalise,
                                    stop=None, trials=6, length_scale=0.4)
    assert [t["elite"] for t in again["trials"]] == [t["elite"] for t in trials]
    with pytest.raises(ValueError, match="--normalise must be none, best or spread"):
        hexgait.trial_and_error(descriptors, prior, damaged, normalise="max")
