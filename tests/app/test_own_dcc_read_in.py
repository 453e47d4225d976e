"""A DCC this register issued is read in as a standard's certificate only byte for byte as
issued and while its certificate is current (hostile78 F4): a polygon cross-calibrated here,
its DCC's face 2 edited from 0.23″ to 3.23″ (its U made smaller), was read by ``analyze
polygon --reference-dcc`` and a certificate issued citing the lab's own certificate for
figures it never stated; the DCC of a withdrawn certificate was read the same. Another
laboratory's DCC is read as before."""

from __future__ import annotations

import json
import random
import re
from pathlib import Path

import pytest

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.dcc.reader import DccError
from models.register.location import register_url
from models.register.store import Register

pytestmark = pytest.mark.slow  # a cross-calibration issued with its DCC, polygon runs


@pytest.fixture(scope="module")
def _own_dcc(tmp_path_factory):
    """The crosscal sample issued with its DCC into a register of its own: the folder."""
    folder = tmp_path_factory.mktemp("own_dcc")
    samples = Path(__file__).resolve().parents[2] / "resources" / "samples"
    meta = json.loads((samples / "certificate_crosscal.json").read_text(encoding="utf-8"))
    meta.pop("issue_date", None)
    meta.update(example=False, certificate_number="", calibration_date="2026-11-20")
    (folder / "cc.json").write_text(json.dumps(meta), encoding="utf-8")
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("ANGLEBENCH_REGISTER", str(folder / "register.sqlite"))
        assert main(["analyze", "crosscal", str(samples / "crosscal_sample.csv"),
                     "--metadata", str(folder / "cc.json"), "--certificate",
                     str(folder / "cc.pdf"), "--dcc", str(folder / "cc.xml")]) == 0
    random.seed(1)
    lines = ["position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec,set,direction"]
    for i in [*range(1, 13), 1]:
        lines.append(f"{i},{(i - 1) * 30 + 10:.6f},0,{random.gauss(0, 0.3):.2f},"
                     f"{random.gauss(0, 0.3):.2f},1,+")
    (folder / "p12.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    return folder


@pytest.fixture
def own(_own_dcc, tmp_path, samples_dir):
    """The module's register, DCC and 12-face run copied into the test's folder, and the
    polygon run's details citing the cross-calibration's certificate; its number."""
    for name in ("register.sqlite", "cc.xml", "p12.csv"):
        (tmp_path / name).write_bytes((_own_dcc / name).read_bytes())
    assert register_url().endswith(str(tmp_path / "register.sqlite"))
    with Register(register_url()) as register:
        number = register.list()[0].number
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.pop("issue_date", None)
    meta.update(example=False, certificate_number="", item_serial="RX-12-0001",
                calibration_date="2026-11-21")
    meta["standards"][0].update(description="12-face polygon", serial="P12-7",
                                certificate_no=number)
    (tmp_path / "p.json").write_text(json.dumps(meta), encoding="utf-8")
    return number


def _read_in(tmp_path, dcc: Path, capsys) -> tuple[int, str]:
    capsys.readouterr()
    code = main(["analyze", "polygon", str(tmp_path / "p12.csv"), "--reference-dcc", str(dcc),
                 "--metadata", str(tmp_path / "p.json"), "--certificate",
                 str(tmp_path / "p.pdf"), "--reading-noise-arcsec", "0.3"])
    return code, capsys.readouterr().err


def _edited(tmp_path) -> Path:
    xml = (tmp_path / "cc.xml").read_text(encoding="utf-8")
    deviations = re.search(r"<si:valueXMLList>0 (-?[0-9.]+) ", xml)
    assert deviations is not None  # face 2's deviation, as the DCC lists the faces
    edited = xml.replace(f"<si:valueXMLList>0 {deviations.group(1)} ",
                         f"<si:valueXMLList>0 {float(deviations.group(1)) + 3:.12g} ")
    assert edited != xml
    (tmp_path / "edited.xml").write_text(edited, encoding="utf-8")
    return tmp_path / "edited.xml"


def test_an_edited_copy_of_the_labs_own_dcc_is_not_read(own, tmp_path, capsys):
    code, err = _read_in(tmp_path, _edited(tmp_path), capsys)
    assert code == 2
    assert (f"edited.xml is a DCC of certificate {own}, which this register issued, but it is "
            "not the DCC it issued") in err
    assert f"anglebench register show {own} --dcc OUT.xml" in err
    assert not (tmp_path / "p.pdf").exists()
    with Register(register_url()) as register:
        assert [r.number for r in register.list()] == [own]  # nothing issued
    # as issued, it is read and the certificate issued citing it
    code, err = _read_in(tmp_path, tmp_path / "cc.xml", capsys)
    assert code == 0, err
    assert (tmp_path / "p.pdf").exists()


def test_the_dcc_of_a_withdrawn_certificate_is_not_read(own, tmp_path, capsys):
    assert main(["register", "withdraw", own, "--reason", "values wrong"]) == 0
    code, err = _read_in(tmp_path, tmp_path / "cc.xml", capsys)
    assert code == 2
    assert (f"cc.xml is the DCC of certificate {own}, which was withdrawn (values wrong): a "
            "withdrawn certificate calibrates nothing") in err
    assert not (tmp_path / "p.pdf").exists()


@pytest.mark.parametrize("number", ["KAL-2026-0009", None])
def test_another_laboratorys_dcc_is_read(own, tmp_path, capsys, number):
    """Another laboratory's DCC of the same polygon, under its own name and number, or one
    numbering as this one (AngleBench's default scheme: the same number) for another item,
    embedding a PDF this register never issued: read as any supplier's."""
    xml = (tmp_path / "cc.xml").read_text(encoding="utf-8")
    if number is None:  # this register's number, another laboratory's item
        xml = xml.replace("<dcc:value>P12-7</dcc:value>", "<dcc:value>Q-77</dcc:value>")
        meta = json.loads((tmp_path / "p.json").read_text(encoding="utf-8"))
        meta["standards"][0]["serial"] = "Q-77"
        (tmp_path / "p.json").write_text(json.dumps(meta), encoding="utf-8")
    else:
        xml = xml.replace(f"<dcc:uniqueIdentifier>{own}</dcc:uniqueIdentifier>",
                          f"<dcc:uniqueIdentifier>{number}</dcc:uniqueIdentifier>")
    # another lab's name, the PDF inside another one's (any bytes)
    other = re.sub(r"<dcc:dataBase64>[^<]*</dcc:dataBase64>",
                   "<dcc:dataBase64>JVBERi0xLjQKJW90aGVyIGxhYgo=</dcc:dataBase64>", xml, count=1)
    lab = json.loads((tmp_path / "p.json").read_text(encoding="utf-8"))["lab_name"]
    other = other.replace(lab, "Another Angle Lab")
    assert "Another Angle Lab" in other
    (tmp_path / "theirs.xml").write_text(other, encoding="utf-8")
    code, err = _read_in(tmp_path, tmp_path / "theirs.xml", capsys)
    assert "which this register issued" not in err
    assert code == 0, err


def test_an_edited_copy_under_another_laboratorys_name_is_still_the_labs_own(
        own, tmp_path, capsys):
    """The laboratory's name changed in the copy, its PDF taken out: still this register's
    number for this register's item, so still not read."""
    xml = _edited(tmp_path).read_text(encoding="utf-8")
    lab = json.loads((tmp_path / "p.json").read_text(encoding="utf-8"))["lab_name"]
    xml, cut = re.subn(r"<dcc:document\b.*?</dcc:document>", "",
                       xml.replace(lab, "Another Lab"), flags=re.S)
    assert cut == 1 and "Another Lab" in xml
    (tmp_path / "renamed.xml").write_text(xml, encoding="utf-8")
    code, err = _read_in(tmp_path, tmp_path / "renamed.xml", capsys)
    assert code == 2
    assert f"renamed.xml is a DCC of certificate {own}, which this register issued" in err


def test_the_window_refuses_an_edited_copy_in_both_readers(own, tmp_path, qtbot):
    """*Load polygon certificate…* (the polygon workbench) and *Read from DCC…* (the details'
    standards) refuse it the same, naming the command that writes the DCC as issued."""
    from widgets.certificate_dialog import CertificateDialog
    from widgets.polygon.presenter import PolygonPresenter

    edited = str(_edited(tmp_path))
    presenter = PolygonPresenter()
    presenter.dcc_register_url = register_url
    with pytest.raises(DccError, match=f"is a DCC of certificate {own}, which this register "
                                       "issued, but it is not the DCC it issued"):
        presenter.load_certificate(edited)
    dialog = CertificateDialog(CertificateMetadata())
    qtbot.addWidget(dialog)
    dialog.dcc_register_url = register_url
    assert not dialog.read_standard_dcc(edited)
    assert "is not the DCC it issued" in dialog.error_label.text()


def test_a_standard_citing_a_withdrawn_certificate_of_this_register_is_refused(
        own, tmp_path, capsys):
    """hostile78 F6: the same without the DCC: the polygon's withdrawn certificate typed as
    its calibration, with a U, was issued citing it."""
    meta = json.loads((tmp_path / "p.json").read_text(encoding="utf-8"))
    meta["standards"][0].update(uncertainty=0.05, uncertainty_unit="arcsec", basis="U95",
                                applies_to="from face 1")
    (tmp_path / "p.json").write_text(json.dumps(meta), encoding="utf-8")
    assert main(["register", "withdraw", own, "--reason", "values wrong"]) == 0
    capsys.readouterr()
    args = ["analyze", "polygon", str(tmp_path / "p12.csv"), "--metadata",
            str(tmp_path / "p.json"), "--reading-noise-arcsec", "0.3", "--certificate"]
    assert main([*args, str(tmp_path / "p.pdf")]) == 2
    assert (f"the reference standard 12-face polygon cites certificate {own}, which this "
            "register withdrew (values wrong): a withdrawn certificate calibrates nothing"
            ) in capsys.readouterr().err
    assert not (tmp_path / "p.pdf").exists()
    # another laboratory's certificate numbered alike, of another polygon: issued
    meta["standards"][0]["serial"] = "Q-77"
    (tmp_path / "p.json").write_text(json.dumps(meta), encoding="utf-8")
    assert main([*args, str(tmp_path / "q.pdf")]) == 0


def test_the_window_gives_its_readers_its_register(window, monkeypatch):
    """The polygon workbench's *Load polygon certificate…* and the details dialog's *Read
    from DCC…* check against the window's register (File › Certificate register)."""
    import app.certificate_dialogs as dialogs

    assert window.presenter("polygon").dcc_register_url() == window.certificates.register_url()
    made = []

    class Dialog(dialogs.CertificateDialog):
        def exec(self):
            made.append(self.dcc_register_url())
            return 0

    monkeypatch.setattr(dialogs, "CertificateDialog", Dialog)
    window.certificates.view.edit_certificate_details(CertificateMetadata(), {}, {})
    assert made == [window.certificates.register_url()]
