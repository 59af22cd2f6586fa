"""check() against proxy-check on the same pair and options: the same counts, intervals, exact
verdicts and class; timings and file names aside."""
import numpy as np
import pytest

import proxyvis
from conftest import data, run_json
from proxyvis_tools.reports import TIMING_KEYS, without

FILE_KEYS = TIMING_KEYS | {"file"}


@pytest.fixture(scope="module")
def pair(bunny, tmp_path_factory):
    """bunny.off and an outside hull proxy of it, written as proxy-check reads it."""
    V, F, _ = bunny
    Vp, Fp, _ = proxyvis.proxy(V, F, kind="outside", method="hull", max_faces=60)
    path = tmp_path_factory.mktemp("pair") / "hull.ply"
    proxyvis.save_mesh(str(path), Vp, Fp)
    return V, F, Vp, Fp, path


@pytest.mark.parametrize("flags", [dict(), dict(seed=7, expect="outside", precision="double")])
def test_check_equals_proxy_check(pair, tmp_path, flags):
    V, F, Vp, Fp, path = pair
    report = proxyvis.check(V, F, Vp, Fp, rays=20000, **flags)
    args = [f"--{k}={v}" for k, v in flags.items()]
    expected = run_json("proxy-check", data("bunny.off"), path, "--rays", 20000, *args,
                        tmp_path=tmp_path)
    assert report["counts"] == expected["counts"] and report["counts"]["HM"] == 0
    assert report["exact"] == expected["exact"] == "contains"
    assert report["sampled_class"] == expected["sampled_class"] and report["ok"]
    assert without(report, FILE_KEYS) == without(expected, FILE_KEYS)
    assert report["original"]["file"] == "V, F" and report["proxy"]["file"] == "Vp, Fp"


def test_check_defaults(pair):
    V, F, Vp, Fp, _ = pair
    report = proxyvis.check(V, F, Vp, Fp, rays=2000)
    assert report["precision"] == "both" and report["seed"] == 0
    assert report["distribution"] == "sphere" and report["rays"] == 2000


def test_expectation_contradicted_is_not_ok(pair):
    V, F, Vp, Fp, _ = pair
    # The bunny lies inside its hull: as a proxy of the hull it is no outside proxy, and
    # proxy-check --expect outside would exit 1.
    report = proxyvis.check(Vp, Fp, V, F, rays=2000, expect="outside")
    assert not report["ok"] and report["contradiction"]


def test_check_settings_errors(pair):
    V, F, Vp, Fp, _ = pair
    for kwargs, text in [(dict(rays=0), "--rays must be in"),
                         (dict(distribution="scene"), "--distribution scene needs a scene"),
                         (dict(precision="half"), "unknown --precision 'half'"),
                         (dict(expect="sideways"), "unknown --expect 'sideways'")]:
        with pytest.raises(proxyvis.Error) as e:
            proxyvis.check(V, F, Vp, Fp, **kwargs)
        assert e.value.exit_code == 2 and text in e.value.message, kwargs


def test_threads_give_the_same_check(pair):
    V, F, Vp, Fp, _ = pair
    one = proxyvis.check(V, F, Vp, Fp, rays=5000, threads=1)
    two = proxyvis.check(V, F, Vp, Fp, rays=5000, threads=2)
    assert without(one, TIMING_KEYS) == without(two, TIMING_KEYS)
