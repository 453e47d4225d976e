"""The JSON contract of U (issue 39): beside every reported error array of every workbench its
expanded_uncertainty_<name> (same length, same unit) and coverage_factor_<name>, the
coverage_probability, and — with a tolerance — a decided_quantity with numbers, its verdict
null and the reason where no statement may be made (U incomplete, U ≥ T)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from app.main import main

pytestmark = pytest.mark.slow  # each runs the command line on a sample (seconds each)

SAMPLES = {
    "theodolite": ("theodolite_sample.csv", ()),
    "polygon": ("polygon_sample.csv", ()),
    "fringe": ("fringe_sample.csv", ("--lines-per-rev", "16384", "--samples-per-period", "64")),
    "positioning": ("positioning_sample.csv", ()),
    "crosscal": ("crosscal_sample.csv", ()),
}
#: the error arrays each workbench reports (a path "object/name" inside an object)
ARRAYS = {
    "theodolite": ("raw_error_arcsec", "model_error_arcsec", "corrected_error_arcsec"),
    "polygon": ("error_arcsec", "pyramidal_error_arcsec", "corrected_error_arcsec",
                "mean_corrected_error_arcsec"),
    "fringe": ("raw_error_arcsec", "compensated_error_arcsec"),
    "positioning": ("per_target/mean_up", "per_target/mean_down"),
    "crosscal": ("encoder_error_arcsec", "polygon_deviation_arcsec",
                 "polygon_deviation_from_face1_arcsec"),
}


def _analyze(capsys, samples_dir, kind: str, metadata=None, tmp_path=None) -> dict:
    name, extra = SAMPLES[kind]
    args = ["analyze", kind, str(samples_dir / name), "--json", *extra]
    if metadata is not None:
        path = tmp_path / "meta.json"
        path.write_text(json.dumps(metadata), encoding="utf-8")
        args += ["--metadata", str(path)]
    code = main(args)
    captured = capsys.readouterr()
    assert code == 0, captured.err
    return json.loads(captured.out)


def _details(samples_dir, kind: str, **changes) -> dict:
    data = json.loads((samples_dir / f"certificate_{kind}.json").read_text(encoding="utf-8"))
    data.update(changes)
    return data


def _at(data: dict, path: str):
    *objects, name = path.split("/")
    for part in objects:
        data = data[part]
    return data, name


@pytest.mark.parametrize("kind", list(SAMPLES))
def test_every_error_array_has_its_u_and_k(kind, capsys, samples_dir, tmp_path):
    data = _analyze(capsys, samples_dir, kind, _details(samples_dir, kind), tmp_path)
    assert data["coverage_probability"] == pytest.approx(0.9545, abs=1e-4)
    for path in ARRAYS[kind]:
        holder, name = _at(data, path)
        errors = np.array(holder[name], dtype=float)
        u = np.array(holder[f"expanded_uncertainty_{name}"], dtype=float)
        k = holder[f"coverage_factor_{name}"]
        assert u.shape == errors.shape, path
        assert np.all(np.isfinite(u)) and np.all(u >= 0), path
        # U is zero only at a reference point, where the error is zero by definition
        zero = u == 0
        assert np.all(np.abs(errors[zero]) < 1e-9), path
        if name != "pyramidal_error_arcsec":  # the correction is exactly known at one face
            assert np.count_nonzero(zero) <= 1, path
        factors = np.broadcast_to(np.asarray(k, dtype=float), u.shape)
        assert np.all((factors >= 1.9) & (factors < 15)), path
        assert np.all(u[~zero] > 0)
    # U's inputs not stated, by name (the positioning sample states no misalignment,
    # resolution or temperature; the fringe's neither its phase reference's U nor the ADC's
    # figures (review 61, F6: the list was empty); the others' details state every input
    # they use)
    assert data["uncertainty_inputs_not_stated"] == {
        "positioning": ["Misalignment of the reference", "Resolution of the reference",
                        "Temperature"],
        "fringe": ["Phase reference", "ADC quantisation", "ADC offset", "ADC gain ratio",
                   "ADC linearity"]}.get(kind, [])
    # the existing keys keep their meaning: cross-calibration's U arrays stay, equal
    if kind == "crosscal":
        assert data["encoder_error_U_arcsec"] == pytest.approx(
            data["expanded_uncertainty_encoder_error_arcsec"], rel=1e-9)


def test_reference_point_u_is_zero_and_the_raw_error_u_leaves_the_model_out(capsys, samples_dir,
                                                                          tmp_path):
    data = _analyze(capsys, samples_dir, "theodolite", _details(samples_dir, "theodolite"),
                    tmp_path)
    raw = np.array(data["expanded_uncertainty_raw_error_arcsec"])
    model = np.array(data["expanded_uncertainty_model_error_arcsec"])
    corrected = np.array(data["expanded_uncertainty_corrected_error_arcsec"])
    assert np.count_nonzero(raw == 0) == 1 and data["raw_error_arcsec"][int(np.argmin(raw))] == 0
    # the model's input is independent of the readings' at every point (same k to a %)
    assert np.allclose(corrected**2, raw**2 + model**2, rtol=0.03)


@pytest.mark.parametrize("kind", ["theodolite", "polygon", "fringe", "positioning"])
def test_decided_quantity_with_a_tolerance(kind, capsys, samples_dir, tmp_path):
    data = _analyze(capsys, samples_dir, kind, _details(samples_dir, kind), tmp_path)
    decided = data["decided_quantity"]
    for key in ("value", "interval_low", "interval_high", "coverage_probability"):
        assert isinstance(decided[key], float), key
    assert decided["interval_low"] <= decided["value"] <= decided["interval_high"]
    assert decided["unit"] == "arcsec" and decided["rule"] in ("simple", "guarded_binary",
                                                               "guarded")
    if decided["verdict"] is None:
        assert decided["reason"]
    else:
        assert decided["verdict"] in ("pass", "conditional pass", "conditional fail", "fail")
        assert 0 <= decided["decision_risk"] <= 1


def test_no_decided_quantity_without_a_tolerance(capsys, samples_dir):
    data = _analyze(capsys, samples_dir, "crosscal")
    assert "decided_quantity" not in data
    data = _analyze(capsys, samples_dir, "theodolite")
    assert "decided_quantity" not in data
    assert data["coverage_probability"] == pytest.approx(0.9545, abs=1e-4)


def test_incomplete_u_gives_numbers_and_no_verdict(capsys, samples_dir, tmp_path):
    """The positioning sample states no misalignment, resolution or temperature: its
    certificate says so, and no statement of conformity is made."""
    decided = _analyze(capsys, samples_dir, "positioning",
                       _details(samples_dir, "positioning"), tmp_path)["decided_quantity"]
    assert decided["verdict"] is None
    assert "not stated" in decided["reason"] and "Temperature" in decided["reason"]
    assert decided["value"] == pytest.approx(9.978, abs=1e-3)
    # no statement, so no probability of conformity or risk resting on the incomplete U
    assert decided["probability_conforming"] is None and decided["decision_risk"] is None
    assert decided["interval_low"] < decided["interval_high"]


def test_inputs_stated_leave_none_unstated(capsys, samples_dir, tmp_path):
    """The positioning sample with its misalignment, resolution and temperature stated: the
    JSON names no input as not stated."""
    name, _ = SAMPLES["positioning"]
    path = tmp_path / "meta.json"
    path.write_text(json.dumps(_details(samples_dir, "positioning")), encoding="utf-8")
    assert main(["analyze", "positioning", str(samples_dir / name), "--json", "--metadata",
                 str(path), "--misalignment-u", "0.2", "--reference-resolution", "0.1",
                 "--temperature-u", "0.3"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["uncertainty_inputs_not_stated"] == []
    assert "not stated" not in (data["decided_quantity"].get("reason") or "")


def test_details_the_settings_contradict_still_give_the_interval(capsys, samples_dir, tmp_path):
    """The polygon's details say grade 3 while the workbench is set to grade 2: the
    certificate is refused, and the JSON still states the decided figure with its interval
    (it does not depend on the tolerance), no verdict, and the refusal as the reason."""
    sample = _details(samples_dir, "polygon")
    assert "grade 3" in sample["item_grade"]
    agreeing = _analyze(capsys, samples_dir, "polygon", sample, tmp_path)["decided_quantity"]
    name, extra = SAMPLES["polygon"]
    path = tmp_path / "meta.json"
    path.write_text(json.dumps(sample), encoding="utf-8")
    assert main(["analyze", "polygon", str(samples_dir / name), "--json", *extra, "--grade", "2",
                 "--metadata", str(path)]) == 0
    decided = json.loads(capsys.readouterr().out)["decided_quantity"]
    assert decided["verdict"] is None and "make them agree" in decided["reason"]
    assert decided["probability_conforming"] is None
    assert decided["value"] == pytest.approx(agreeing["value"])
    assert decided["interval_low"] == pytest.approx(agreeing["interval_low"])
    assert decided["interval_high"] == pytest.approx(agreeing["interval_high"])
    assert decided["tolerance"] == pytest.approx(0.5)  # grade 2's, the settings'


# the sample's U is 1.44" per point (the reading error counted once, #39; 2.01" before), the
# half range's interval −1.4"/+0"
@pytest.mark.parametrize(("quantity", "tolerance"), [("points", 1.4), ("half_range", 0.05)])
def test_u_not_smaller_than_t_gives_numbers_and_no_verdict(quantity, tolerance, capsys,
                                                           samples_dir, tmp_path):
    details = _details(samples_dir, "theodolite", tolerance=tolerance,
                       decision_quantity=quantity)
    decided = _analyze(capsys, samples_dir, "theodolite", details, tmp_path)["decided_quantity"]
    assert decided["verdict"] is None and "not smaller than" in decided["reason"]
    # U ≥ T on either side of the interval (the lower one, for the half range's)
    assert max(decided["interval_high"] - decided["value"],
               decided["value"] - decided["interval_low"]) >= tolerance
    assert decided["tolerance"] == tolerance


def test_u_not_determined_is_null_with_the_reason(capsys, tmp_path):
    """A target approached once has no repeatability: U is not determined, said so."""
    path = tmp_path / "log.csv"
    path.write_text("target,run,direction,deviation\n0,1,+,1.0\n0,2,+,1.2\n10,1,+,2.0\n"
                    "20,1,+,2.5\n20,2,+,2.4\n", encoding="utf-8")
    assert main(["analyze", "positioning", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["per_target"]["expanded_uncertainty_mean_up"] is None
    assert "approached fewer than twice" in data["uncertainty_withheld"]


@pytest.mark.parametrize("kind", ["polygon", "fringe"])
def test_every_u_array_has_its_k_beside_it(kind, capsys, samples_dir, tmp_path):
    """Beside every expanded_uncertainty_<name> its coverage_factor_<name> (audit cov76: the
    fringe's offsets_v had its k only as parameters_coverage_factor, which stays), and the
    polygon's reversal_arcsec its U: null with the reason where a direction has one set
    (the sample: one set each way), as B and B̄."""
    data = _analyze(capsys, samples_dir, kind, _details(samples_dir, kind), tmp_path)
    # the arrays' (a single parameter's U, the amplitude ratio's, has the table's k)
    names = [key[len("expanded_uncertainty_"):] for key in data
             if key.startswith("expanded_uncertainty_")
             and isinstance(data.get(key[len("expanded_uncertainty_"):]), list)]
    assert names
    for name in names:
        assert f"coverage_factor_{name}" in data, name
    if kind == "fringe":
        assert data["coverage_factor_offsets_v"] == data["parameters_coverage_factor"]
    else:
        assert "reversal_arcsec" in names and data["reversal_arcsec"] is not None
        assert data["expanded_uncertainty_reversal_arcsec"] is None
        assert data["coverage_factor_reversal_arcsec"] is None
        assert data["reversal_uncertainty_reason"].startswith("one set per direction")
