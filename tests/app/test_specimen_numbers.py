"""A SPECIMEN's number follows what it states (assessment 70, L2): the same readings,
settings and details give the same number, every time; other results with the same details
another (until 0.8.18 the number came from the details alone, so the theodolite sample,
its 9-point run and its run at another accuracy were all SPECIMEN-CD124E98)."""

from __future__ import annotations

import json

import pytest

from app.certificate_issue import specimen_document
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

pytestmark = pytest.mark.slow  # five analyses of the theodolite sample and their documents


def _specimen_number(samples_dir, path, settings=None) -> str:
    kind = KINDS["theodolite"]
    table = read_table(str(path))
    parsed = ReadingsSheet(kind.columns, map_columns(table, kind.columns)).parse()
    settings = kind.settings_with_defaults(settings or {})
    result = kind.analyze(parsed, settings)
    details = json.loads((samples_dir / "certificate_theodolite.json").read_text("utf-8"))
    document = kind.certificate_document(result, CertificateMetadata.from_dict(details),
                                         path.name, settings)  # as the command line does
    return specimen_document(document).metadata.certificate_number


def test_the_same_run_gives_the_same_number_and_other_results_another(samples_dir, tmp_path):
    sample = samples_dir / "theodolite_sample.csv"
    number = _specimen_number(samples_dir, sample)
    assert number.startswith("SPECIMEN-")
    assert _specimen_number(samples_dir, sample) == number  # reproducible
    # the same readings judged at another accuracy of the theodolite: other results
    assert _specimen_number(samples_dir, sample, {"accuracy_arcsec": 0.2}) != number
    # one azimuth reading 1" larger (the first row's), the same details: other readings
    lines = sample.read_text("utf-8").splitlines()
    assert lines[1].startswith('-20,"-19°52\'57.0""",')
    lines[1] = lines[1].replace('57.0""', '58.0""', 1)
    other = tmp_path / "one_reading_changed.csv"
    other.write_text("\n".join(lines) + "\n", "utf-8")
    assert _specimen_number(samples_dir, other) != number
    # nine points of the run: fewer readings
    nine = tmp_path / "nine_points.csv"
    nine.write_text("\n".join(sample.read_text("utf-8").splitlines()[:10]) + "\n", "utf-8")
    assert _specimen_number(samples_dir, nine) != number



def test_the_same_results_in_any_language_give_the_same_number(samples_dir):
    """Assessment 72 L8: the theodolite sample issued in en and in zh were SPECIMEN-9D13E820
    and SPECIMEN-9C7ACC74; a specimen numbers the results, not the language they are read
    in. One analysis, its certificate in each language (the details otherwise the same)."""
    kind = KINDS["theodolite"]
    sample = samples_dir / "theodolite_sample.csv"
    parsed = ReadingsSheet(kind.columns, map_columns(read_table(str(sample)), kind.columns)).parse()
    settings = kind.settings_with_defaults({})
    result = kind.analyze(parsed, settings)
    details = json.loads((samples_dir / "certificate_theodolite.json").read_text("utf-8"))

    def number(**changed) -> str:
        document = kind.certificate_document(
            result, CertificateMetadata.from_dict(details | changed), sample.name, settings)
        return specimen_document(document).metadata.certificate_number

    numbers = {language: number(language=language) for language in ("en", "zh", "zh+en")}
    assert len(set(numbers.values())) == 1, numbers
    # the details still count: another customer, another number
    assert number(language="en", customer_name="Another customer") != numbers["en"]
