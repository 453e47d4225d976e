"""The details' switch "Decision rule agreed with the customer" (assessment 76 L5, ISO/IEC
17025 7.1.3) shows the details' ``decision_rule_agreed`` and gives it back; a certificate's
own, not a lab default."""

from __future__ import annotations

import pytest

from models.certificate.metadata import LAB_DEFAULT_FIELDS, CertificateMetadata
from widgets.certificate_dialog import CertificateDialog


@pytest.mark.parametrize("agreed", [True, False])
def test_the_switch_shows_and_gives_back_the_agreement(qtbot, agreed):
    dialog = CertificateDialog(CertificateMetadata(decision_rule_agreed=agreed))
    qtbot.addWidget(dialog)
    assert dialog.rule_agreed.isChecked() is agreed
    assert dialog.raw_values()["decision_rule_agreed"] is agreed
    dialog.rule_agreed.setChecked(not agreed)
    assert CertificateMetadata.from_dict(dialog.raw_values()).decision_rule_agreed is (not agreed)
    assert "decision_rule_agreed" not in LAB_DEFAULT_FIELDS
