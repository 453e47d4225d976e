"""Dialog for a certificate's metadata: lab, customer, item, reference standards,
environment, people, dates and the decision rule.

The dialog only edits fields; :meth:`CertificateDialog.metadata` turns them
into a :class:`CertificateMetadata` (which checks them), and a field that
cannot be used is marked red with the reason, the rest of the entry kept.
"""

from __future__ import annotations

import datetime as dt
import re
from collections.abc import Callable
from typing import Any

from PySide6.QtCore import QT_TR_NOOP, QEvent, QSize, Qt, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QPlainTextEdit,
    QPushButton,
    QScrollArea,
    QStyle,
    QStyleOptionFrame,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from models.certificate.metadata import (
    DECISION_RULES,
    LANGUAGES,
    PLACES,
    CertificateMetadata,
    MetadataError,
)
from models.messages import in_language, translator
from models.quantity import UNITS
from models.uncertainty.conformity import DECISION_RULE_NAMES
from widgets.i18n import declared, explained, tr, translated
from widgets.open_file import ask_open_file
from widgets.screen_fit import fit_to_screen

__all__ = ["CertificateDialog"]


# QT_TR_NOOP marks a text for lupdate; tr() translates it where it is shown
_TEXT_FIELDS = {
    "certificate_number": QT_TR_NOOP("Certificate number"),
    "issue_date": QT_TR_NOOP("Date of issue (YYYY-MM-DD)"),
    "calibration_date": QT_TR_NOOP("Date of calibration"),
    "tolerance": QT_TR_NOOP("Tolerance ±"),
    "lab_name": QT_TR_NOOP("Laboratory"), "lab_address": QT_TR_NOOP("Address"),
    "lab_accreditation": QT_TR_NOOP("Accreditation"), "number_scheme": QT_TR_NOOP("Number scheme"),
    "customer_name": QT_TR_NOOP("Customer"), "customer_address": QT_TR_NOOP("Address"),
    "item_description": QT_TR_NOOP("Item under test"), "item_manufacturer": QT_TR_NOOP("Manufacturer"),
    "item_serial": QT_TR_NOOP("Serial number"), "item_grade": QT_TR_NOOP("Grade / specification"),
    "item_model": QT_TR_NOOP("Model / type"),
    "lab_country": QT_TR_NOOP("Country (ISO 3166-1, e.g. CN)"),
    "calibration_site": QT_TR_NOOP("Customer's site (where)"),
    "item_resolution": QT_TR_NOOP("Resolution"),
    "temperature_c": QT_TR_NOOP("Temperature (°C)"),
    "humidity_pct": QT_TR_NOOP("Relative humidity (%)"), "operator": QT_TR_NOOP("Operator"),
    "approver": QT_TR_NOOP("Approved by"), "checker": QT_TR_NOOP("Checked by"),
    "coverage_probability_pct": QT_TR_NOOP("Coverage probability (%)"),
    "as_left_table_sha256": QT_TR_NOOP("Table loaded (sha256)"),
}
# choice fields: key -> (label, {value: text})
_CHOICES = {
    "document_type": (QT_TR_NOOP("Document"), {"calibration": QT_TR_NOOP("Calibration certificate"),
                                           "test": QT_TR_NOOP("Test report")}),
    "language": (QT_TR_NOOP("Language"), LANGUAGES),
    "calibration_place": (QT_TR_NOOP("Place of calibration"), PLACES),
    "decision_rule": (QT_TR_NOOP("Decision rule"), DECISION_RULE_NAMES),
    "decision_quantity": (QT_TR_NOOP("Decided quantity"), {
        "half_range": QT_TR_NOOP("Half the peak-to-peak (Monte Carlo U)"),
        "points": QT_TR_NOOP("Every point with its own U")}),
}
# a figure typed with its unit, chosen beside it: field -> the key of its unit
_UNIT_OF = {"tolerance": "tolerance_unit", "item_resolution": "item_resolution_unit"}
_STANDARD_COLUMNS = ("description", "serial", "certificate_no", "uncertainty", "basis",
                     "applies_to", "uncertainty_unit", "role", "due_date")
_STANDARD_HEADERS = (QT_TR_NOOP("Standard"), QT_TR_NOOP("Serial no."), QT_TR_NOOP("Certificate no."),
                     QT_TR_NOOP("Uncertainty"), QT_TR_NOOP("Stated as (U95, MPE, u)"),
                     QT_TR_NOOP("Per (reading, angle, from face 1)"),
                     QT_TR_NOOP("Unit of the uncertainty (\", µrad, nm, µm …)"),
                     # which standard of the measurand it is (assessment 72 L2)
                     QT_TR_NOOP("Role (reference, autocollimator, adc)"),
                     QT_TR_NOOP("Due date (YYYY-MM-DD)"))
_ERROR_STYLE = "background: #ffd7d7;"


def _two_lines(text: str) -> str:
    """A long header broken at the space nearest its middle."""
    spaces = [i for i, c in enumerate(text) if c == " "]
    if len(text) < 16 or not spaces:
        return text
    cut = min(spaces, key=lambda i: abs(i - len(text) / 2))
    return f"{text[:cut]}\n{text[cut + 1:]}"


def _text_width(edit: QLineEdit, text: str) -> int:
    """The width ``edit`` takes to show ``text`` whole (not elided: "…TRUSTED_CERTIFICAT…")."""
    option = QStyleOptionFrame()
    edit.initStyleOption(option)
    # 2 px a side inside the frame: QLineEdit's own margin around its text
    contents = QSize(edit.fontMetrics().horizontalAdvance(text) + 4 + 1, edit.fontMetrics().height())
    margins = edit.textMargins()
    contents += QSize(margins.left() + margins.right(), 0)
    return edit.style().sizeFromContents(QStyle.ContentsType.CT_LineEdit, option, contents,
                                         edit).width()


class _Sections(QWidget):
    """The dialog's groups two a row where the width has room for both side by side, else
    one below the other: the details never scroll sideways (at 200 % on a 1280×720 screen,
    640 logical pixels, the Laboratory column was behind a horizontal scroll bar, and in the
    1100 px screenshot cut in half)."""

    def __init__(self) -> None:
        super().__init__()
        self._grid = QGridLayout(self)
        self._rows: list[tuple[QWidget, QWidget | None]] = []  # (left, right); (wide, None)
        self.columns = 0

    def add_row(self, left: QWidget, right: QWidget | None = None) -> None:
        self._rows.append((left, right))

    def two_columns_width(self) -> int:
        """The least width the groups take two a row."""
        spacing = self._grid.horizontalSpacing()
        margins = self._grid.contentsMargins()
        pairs = [(left, right) for left, right in self._rows if right is not None]
        lefts = max((left.minimumSizeHint().width() for left, _ in pairs), default=0)
        rights = max((right.minimumSizeHint().width() for _, right in pairs), default=0)
        wide = max((left.minimumSizeHint().width() for left, right in self._rows
                    if right is None), default=0)
        return max(lefts + spacing + rights, wide) + margins.left() + margins.right()

    def set_columns(self, columns: int) -> None:
        """The groups two a row (``columns`` 2) or one below the other (1)."""
        if columns == self.columns:
            return
        for left, right in self._rows:
            for widget in (left, right):
                if widget is not None:
                    self._grid.removeWidget(widget)
        row = 0
        for left, right in self._rows:
            if right is None:
                self._grid.addWidget(left, row, 0, 1, columns)
            elif columns == 2:
                self._grid.addWidget(left, row, 0)
                self._grid.addWidget(right, row, 1)
            else:
                self._grid.addWidget(left, row, 0)
                row += 1
                self._grid.addWidget(right, row, 0)
            row += 1
        self.columns = columns


class CertificateDialog(QDialog):
    """Edit certificate metadata; ``lab_defaults_saved`` carries the lab-wide fields."""

    lab_defaults_saved = Signal(dict)
    #: the lab's time zone (an IANA name, checked; empty: the system's), on Export or save
    lab_timezone_set = Signal(str)

    def __init__(self, metadata: CertificateMetadata, parent: QWidget | None = None,
                 timezone: str = "") -> None:
        super().__init__(parent)
        self.setWindowTitle(tr("Certificate details"))
        self.fields: dict[str, QLineEdit] = {}
        #: the details as they were when *Save as lab defaults* was pressed: kept with the
        #: project even if the dialog is then cancelled (rev62day F15: the customer and item
        #: typed were lost)
        self.saved_details: CertificateMetadata | None = None
        #: the register a DCC of this lab's own is checked against ("": none; hostile78 F4)
        self.dcc_register_url: Callable[[], str] = lambda: ""
        self._setup_ui()
        self.set_metadata(metadata)
        self.timezone.setText(timezone)

    # -- layout -------------------------------------------------------------
    def _line(self, key: str) -> QLineEdit:
        edit = QLineEdit()
        edit.setObjectName(key)
        edit.textEdited.connect(lambda _t, e=edit: e.setStyleSheet(""))
        self.fields[key] = edit
        return edit

    def _group(self, title: str, keys: tuple[str, ...]) -> QGroupBox:
        box = QGroupBox(tr(title))
        form = QFormLayout(box)
        # a field without room beside its caption goes below it (the decision rule's choice
        # beside "Trusted certificate for DCCs read (PEM file)" needs ~650 px)
        form.setRowWrapPolicy(QFormLayout.RowWrapPolicy.WrapLongRows)
        for key in keys:
            if key == "certificate_number":
                edit = self._line(key)
                edit.setPlaceholderText(tr("allocated by the register on export"))
                edit.setToolTip(tr("Leave empty: the register allocates the next number of the "
                                   "scheme, unique across every workstation sharing it. A number "
                                   "typed here is refused if it was issued before."))
                form.addRow(tr(_TEXT_FIELDS[key]), edit)
            elif key in _UNIT_OF:  # the number, and its unit beside it
                row = QHBoxLayout()
                row.addWidget(self._line(key), 1)
                row.addWidget(self._unit_box(_UNIT_OF[key]))
                form.addRow(tr(_TEXT_FIELDS[key]), row)
            else:
                form.addRow(tr(_TEXT_FIELDS[key]), self._line(key))
        return box

    def _unit_box(self, key: str) -> QComboBox:
        """A unit of models.quantity to choose (the errors' own, or one of their kind)."""
        box = QComboBox()
        box.setObjectName(key)
        for unit_key, unit in UNITS.items():
            box.addItem(unit.symbol, unit_key)
        box.setToolTip(tr("The unit of the figure beside it: converted to the unit of the "
                          "errors (an angle cannot be judged against a length)"))
        self.choices[key] = box
        return box

    def _setup_ui(self) -> None:
        sections = self.sections = _Sections()
        self.choices: dict[str, QComboBox] = {}
        cert = self._group(QT_TR_NOOP("Certificate"), ("certificate_number", "issue_date", "calibration_date",
                                           "tolerance", "coverage_probability_pct",
                                           "as_left_table_sha256", "calibration_site"))
        self.fields["issue_date"].setToolTip(tr(
            "A draft prints this date; an issued certificate is dated the day the register "
            "issues it"))
        self.fields["as_left_table_sha256"].setToolTip(tr(
            "Fringe: the checksum of the correction table loaded into the encoder (printed in "
            "the exported table); the compensated error is then stated as left"))
        for key, (label, options) in _CHOICES.items():
            box = QComboBox()
            box.setObjectName(key)
            for value, text in options.items():
                box.addItem(declared(text) if key == "language" else tr(text), value)
                if key == "decision_rule":
                    box.setItemData(box.count() - 1, DECISION_RULES[value],
                                    Qt.ItemDataRole.ToolTipRole)
            self.choices[key] = box
            cert.layout().addRow(tr(label), box)
        self.decision_rule = self.choices["decision_rule"]
        # ISO/IEC 17025 7.1.3: the rule agreed with this customer (the certificate says so,
        # or that it is the rule requested with no agreement recorded: assessment 76 L5)
        self.rule_agreed = QCheckBox(tr("Decision rule agreed with the customer"))
        self.rule_agreed.setObjectName("decision_rule_agreed")
        self.rule_agreed.setToolTip(tr(
            "ISO/IEC 17025 7.1.3: the decision rule was communicated to and agreed with the "
            "customer (a contract or an order that records it). The certificate says so; "
            "unticked, it says the rule is the one requested, with no agreement recorded"))
        # right under the rule it qualifies
        rule_row = cert.layout().getWidgetPosition(self.decision_rule)[0]
        cert.layout().insertRow(rule_row + 1, "", self.rule_agreed)
        # the training switch: a specimen exactly as "example": true makes one on the command
        # line (watermarked, numbered SPECIMEN-…, recorded in no register)
        self.training = QCheckBox(tr("Training / specimen"))
        self.training.setObjectName("example")
        self.training.setToolTip(tr(
            "A specimen for training or demonstration: watermarked SPECIMEN, numbered "
            "SPECIMEN-…, not a certificate, and recorded in no register"))
        cert.layout().addRow("", self.training)
        # the digital certificate beside the PDF (PTB DCC 3.3.0: the XML with the PDF inside)
        self.write_dcc = QCheckBox(tr("Also write the digital certificate (DCC, XML)"))
        self.write_dcc.setObjectName("write_dcc")
        self.write_dcc.setToolTip(tr(
            "Beside the PDF, the same certificate as a PTB Digital Calibration Certificate "
            "(DCC 3.3.0 XML, the PDF embedded in it), in the same folder with the ending .xml"))
        cert.layout().addRow("", self.write_dcc)
        self.dcc_schema = QLineEdit()
        self.dcc_schema.setObjectName("dcc_schema_dir")
        self.dcc_schema.setPlaceholderText(tr("empty: the DCC is not validated"))
        self.dcc_schema.setToolTip(tr(
            "The folder of PTB's DCC 3.3.0 schema set (dcc.xsd, si/, d-sig/): every DCC is "
            "validated against it and not written when invalid"))
        cert.layout().addRow(tr("DCC schema folder"), self.dcc_schema)
        # the lab's signature on its DCCs: paths of PEM files only (their content is read
        # when a DCC is signed or checked, never stored)
        self.dcc_signing = {}
        for name, label, placeholder, tip in (
                ("dcc_signing_key", tr("DCC signing key (PEM file)"),
                 tr("empty: ANGLEBENCH_DCC_SIGNING_KEY, else not signed"),
                 tr("The laboratory's private key file (PEM) its DCCs are signed with "
                    "(XML-DSig); only the path is kept")),
                ("dcc_signing_certificate", tr("DCC signing certificate (PEM file)"),
                 tr("empty: ANGLEBENCH_DCC_SIGNING_CERTIFICATE"),
                 tr("The X.509 certificate (PEM) of the signing key, carried in each signed "
                    "DCC")),
                ("dcc_trusted_certificate", tr("Trusted certificate for DCCs read (PEM file)"),
                 tr("empty: ANGLEBENCH_DCC_TRUSTED_CERTIFICATE, else the signing certificate"),
                 tr("A signature on a DCC read in (a standard's, a polygon's) is checked "
                    "against this certificate"))):
            edit = QLineEdit()
            edit.setObjectName(name)
            edit.setPlaceholderText(placeholder)
            edit.setToolTip(tip)
            cert.layout().addRow(label, edit)
            self.dcc_signing[name] = edit
        lab = self._group(QT_TR_NOOP("Laboratory"), ("lab_name", "lab_address", "lab_accreditation",
                                                    "lab_country", "number_scheme"))
        # the lab's template: a checker signs as well (核验员, JJF 1071's model)
        self.checker_role = QCheckBox(tr("Certificates are checked (Checked by / 核验员)"))
        self.checker_role.setObjectName("checker_role")
        self.checker_role.setToolTip(tr(
            "The lab's template asks for a checker: the signature block reads Calibrated by / "
            "Checked by / Approved by, and a certificate without a checker is a draft"))
        lab.layout().addRow("", self.checker_role)
        # the lab's time zone: a window setting, not a detail of this certificate
        self.timezone = QLineEdit()
        self.timezone.setObjectName("lab_timezone")
        self.timezone.setPlaceholderText(tr("the system's (e.g. Asia/Shanghai)"))
        self.timezone.setToolTip(tr(
            "The lab's time zone (an IANA name such as Asia/Shanghai): an issued certificate "
            "is dated the lab's local date. Empty: ANGLEBENCH_TIMEZONE, else the system's"))
        self.timezone.textEdited.connect(lambda _t: self.timezone.setStyleSheet(""))
        lab.layout().addRow(tr("Time zone"), self.timezone)
        sections.add_row(cert, lab)
        sections.add_row(
            self._group(QT_TR_NOOP("Customer"), ("customer_name", "customer_address")),
            self._group(QT_TR_NOOP("Item under test"), (
                "item_description", "item_manufacturer", "item_model", "item_serial",
                "item_grade", "item_resolution")))
        people = self._group(QT_TR_NOOP("Environment and people"), (
            "temperature_c", "humidity_pct", "operator", "checker", "approver"))
        notes_box = QGroupBox(tr("Remarks printed on the certificate"))
        self.notes = QPlainTextEdit()
        self.notes.setObjectName("notes")
        QVBoxLayout(notes_box).addWidget(self.notes)
        sections.add_row(people, notes_box)

        standards_box = QGroupBox(tr("Reference standards (their uncertainty enters the budget "
                                     "per reading)"))
        self.standards = QTableWidget(0, len(_STANDARD_COLUMNS))
        # headers in two lines where long, every column as wide as its header (stretched,
        # they were cut: "Stated as (U95, MPE, u"), three rows in sight (#31)
        self.standards.setHorizontalHeaderLabels([_two_lines(tr(h)) for h in _STANDARD_HEADERS])
        self.standards.horizontalHeader().setSectionResizeMode(
            QHeaderView.ResizeMode.ResizeToContents)
        self.standards.horizontalHeader().setStretchLastSection(True)
        self.standards.setMinimumHeight(
            self.standards.horizontalHeader().sizeHint().height()
            + 3 * self.standards.verticalHeader().defaultSectionSize()
            + self.standards.horizontalScrollBar().sizeHint().height()
            + 2 * self.standards.frameWidth())
        self.standards.itemChanged.connect(lambda item: item.setBackground(Qt.GlobalColor.white))
        buttons = QHBoxLayout()
        add, remove = QPushButton(tr("Add standard")), QPushButton(tr("Remove standard"))
        add.clicked.connect(lambda: self.add_standard({}))
        remove.clicked.connect(self._remove_standard)
        from_dcc = QPushButton(tr("Read from DCC…"))
        from_dcc.setObjectName("standard_from_dcc")
        from_dcc.setToolTip(tr("Fill the selected standard's certificate number, uncertainty "
                               "and due date from its digital calibration certificate (DCC "
                               "XML); a new row when none is selected"))
        from_dcc.clicked.connect(self._ask_standard_dcc)
        buttons.addWidget(add)
        buttons.addWidget(remove)
        buttons.addWidget(from_dcc)
        buttons.addStretch(1)
        box_layout = QVBoxLayout(standards_box)
        box_layout.addWidget(self.standards)
        box_layout.addLayout(buttons)
        sections.add_row(standards_box)

        # what the certificate will say of its readings' origin, read before issue (day
        # review 67 F7: seen only in the issued PDF, after the register recorded it)
        self.readings_caption = QLabel(tr("Readings, as the certificate will say:"))
        self.readings_caption.setObjectName("readings_caption")
        self.readings_line = QLabel()
        self.readings_line.setObjectName("readings_line")
        self.readings_line.setWordWrap(True)
        self.readings_line.setTextFormat(Qt.TextFormat.PlainText)
        self.readings_line.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.readings_line.setToolTip(tr(
            "Where the readings came from, as the certificate prints it in its language. To "
            "change it, change the readings (or save the project) before exporting."))
        self._readings: str = ""
        for widget in (self.readings_caption, self.readings_line):
            widget.setVisible(False)
        self.choices["language"].currentIndexChanged.connect(self._show_readings_line)
        self.error_label = QLabel()
        self.error_label.setStyleSheet("color: #b00020;")
        self.error_label.setWordWrap(True)
        self.buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                        | QDialogButtonBox.StandardButton.Cancel)
        self.buttons.button(QDialogButtonBox.StandardButton.Ok).setText(tr("Export…"))
        self.save_defaults_button = self.buttons.addButton(
            tr("Save as lab defaults"), QDialogButtonBox.ButtonRole.ActionRole)
        self.save_defaults_button.setToolTip(tr("Lab, number scheme, standards, people and "
                                                "decision rule become the start of every new "
                                                "certificate"))
        self.save_defaults_button.clicked.connect(self._save_lab_defaults)
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        # the details scroll, the message and the buttons stay in sight: the dialog fits a
        # 1280×720 screen and 200 % scale (it is ~870 px tall unscrolled)
        sections.set_columns(2)
        for edit in sections.findChildren(QLineEdit):  # a hint in a field is read whole
            if edit.placeholderText():
                edit.setMinimumWidth(_text_width(edit, edit.placeholderText()))
        self.details_area = QScrollArea()
        self.details_area.setWidgetResizable(True)
        self.details_area.setWidget(sections)
        self.details_area.installEventFilter(self)
        layout = QVBoxLayout(self)
        layout.addWidget(self.details_area, 1)
        layout.addWidget(self.readings_caption)
        layout.addWidget(self.readings_line)
        layout.addWidget(self.error_label)
        layout.addWidget(self.buttons)
        wanted = sections.sizeHint()
        bar = self.details_area.verticalScrollBar().sizeHint().width()
        fit_to_screen(self, wanted.width() + bar + 40,
                      wanted.height() + self.buttons.sizeHint().height() + 60)

    def eventFilter(self, watched, event) -> bool:  # noqa: N802 - Qt's name
        if watched is self.details_area and event.type() == QEvent.Type.Resize:
            self._reflow()
        return False

    def _reflow(self) -> None:
        """The groups two a row where the details area has room for both beside a vertical
        scroll bar, else one below the other."""
        area = self.details_area
        room = area.maximumViewportSize().width() - area.verticalScrollBar().sizeHint().width()
        self.sections.set_columns(2 if room >= self.sections.two_columns_width() else 1)

    # -- values -------------------------------------------------------------
    def set_readings_line(self, line: str) -> None:
        """Show the certificate's "Readings:" line (models/certificate/readings_origin.py,
        a Message), read-only, in the language chosen for the certificate: as a Chinese
        certificate prints it in Chinese, an English or a bilingual one in English."""
        self._readings = line
        for widget in (self.readings_caption, self.readings_line):
            widget.setVisible(bool(line))
        self._show_readings_line()

    def _show_readings_line(self, *_args) -> None:
        line = self._readings
        if self.choices["language"].currentData() == "zh":
            line = in_language(line, translator("zh_CN"))
        self.readings_line.setText(str(line))

    def set_metadata(self, meta: CertificateMetadata) -> None:
        data = meta.to_dict()
        for key, edit in self.fields.items():
            value = data.get(key)
            edit.setText("" if value is None else f"{value:g}" if isinstance(value, float)
                         else str(value))
        for key, box in self.choices.items():
            box.setCurrentIndex(max(box.findData(data.get(key)), 0))
        self.notes.setPlainText(meta.notes)
        self.training.setChecked(meta.example)
        self.checker_role.setChecked(meta.checker_role)
        self.rule_agreed.setChecked(meta.decision_rule_agreed)
        if not meta.issue_date:
            self.fields["issue_date"].setText(dt.date.today().isoformat())
        self.standards.setRowCount(0)
        for standard in data["standards"]:
            self.add_standard(standard)

    def add_standard(self, standard: dict[str, Any]) -> None:
        row = self.standards.rowCount()
        self.standards.insertRow(row)
        for col, key in enumerate(_STANDARD_COLUMNS):
            value = standard.get(key)
            text = "" if value is None else f"{value:g}" if isinstance(value, float) else str(value)
            if key == "basis" and not text:
                text = "U95"
            if key == "applies_to" and not text:
                text = "reading"
            if key == "uncertainty_unit" and not text:
                text = "arcsec"
            self.standards.setItem(row, col, QTableWidgetItem(text))

    def _ask_standard_dcc(self) -> None:
        path = ask_open_file(self, tr("Standard's digital calibration certificate"), "",
                             tr("DCC (*.xml);;All files (*)"))
        if path:
            self.read_standard_dcc(path)

    def read_standard_dcc(self, path: str, schema_dir: str = "") -> bool:
        """Replace a standard's certificate as a whole from the DCC at ``path`` — number,
        serial (where the row lists none), uncertainty with its basis, unit and what it is
        per, due date, every one the DCC speaks to or emptied — in the selected row, else a
        new one. A DCC refused (schema, unit, signature, expired before the date of
        calibration — today's when the field holds no date —, another item's) changes
        nothing and says why; what the reader notes (no due date, an unchecked signer) is
        said."""
        from models.dcc.reader import DccError, read_standard_dcc
        from models.dcc.signature import SigningError, signature_demanded, trusted_certificate
        from models.register.read_in import own_dcc_refusal_at

        when = self.fields["calibration_date"].text().strip() if (
            "calibration_date" in self.fields) else ""
        try:
            dt.date.fromisoformat(when)
        except ValueError:
            when = dt.date.today().isoformat()  # no date typed yet: the calibration is today's
        rows = sorted({i.row() for i in self.standards.selectedIndexes()})

        def cell(row: int, key: str) -> str:
            item = self.standards.item(row, _STANDARD_COLUMNS.index(key))
            return item.text() if item is not None else ""

        try:
            import os

            # as app/dcc_issue.dcc_schema_dir: the one given, the environment's, the field's
            schema_dir = (schema_dir or os.environ.get("ANGLEBENCH_DCC_SCHEMA", "")
                          or self.dcc_schema.text()).strip()
            trust = self.dcc_signing["dcc_trusted_certificate"].text()
            # this register's own DCC: read as issued, and while current (hostile78 F4)
            url = self.dcc_register_url()
            refused = own_dcc_refusal_at(url, path) if url else None
            if refused is not None:
                raise DccError(refused)
            found = read_standard_dcc(path, schema_dir or None, measurement_date=when,
                                      trusted_cert=trusted_certificate(trust),
                                      trust_named=signature_demanded(trust))
            # the row's standard must be the DCC's item: checked before anything changes
            fields, said = found.for_standard(*((cell(rows[0], "description"),
                                                 cell(rows[0], "serial")) if rows else ("", "")))
        except (DccError, SigningError) as exc:
            self.error_label.setStyleSheet("color: #b00020;")
            self.error_label.setText(explained(exc))
            return False
        if rows:
            row = rows[0]
        else:
            self.add_standard({})
            row = self.standards.rowCount() - 1
        for key, value in fields.items():
            text = f"{value:.6g}" if isinstance(value, float) else str(value)
            self.standards.setItem(row, _STANDARD_COLUMNS.index(key), QTableWidgetItem(text))
        self.error_label.setStyleSheet("")
        self.error_label.setText("\n".join(translated(n) for n in (*found.notes, *said)))
        return True

    def _remove_standard(self) -> None:
        rows = sorted({i.row() for i in self.standards.selectedIndexes()}, reverse=True)
        for row in rows or [self.standards.rowCount() - 1]:
            if row >= 0:
                self.standards.removeRow(row)

    def raw_values(self) -> dict[str, Any]:
        data: dict[str, Any] = {key: edit.text() for key, edit in self.fields.items()}
        for key, box in self.choices.items():
            data[key] = box.currentData()
        data["notes"] = self.notes.toPlainText()
        data["example"] = self.training.isChecked()
        data["checker_role"] = self.checker_role.isChecked()
        data["decision_rule_agreed"] = self.rule_agreed.isChecked()
        standards = []
        for row in range(self.standards.rowCount()):
            entry = {key: (self.standards.item(row, col).text()
                           if self.standards.item(row, col) else "")
                     for col, key in enumerate(_STANDARD_COLUMNS)}
            if any(v.strip() for k, v in entry.items()
                   if k not in ("basis", "applies_to", "uncertainty_unit", "role")):
                standards.append(entry)
        data["standards"] = standards
        return data

    def dcc_options(self) -> tuple[bool, str]:
        """Whether to write the DCC beside the PDF, and the schema folder (window settings,
        not details of this certificate)."""
        return self.write_dcc.isChecked(), self.dcc_schema.text().strip()

    def set_dcc_options(self, write: bool, schema_dir: str) -> None:
        self.write_dcc.setChecked(write)
        self.dcc_schema.setText(schema_dir)

    def dcc_signing_paths(self) -> tuple[str, str, str]:
        """The signing key, its certificate and the trusted certificate (paths; lab
        settings, not details of this certificate)."""
        return tuple(self.dcc_signing[name].text().strip() for name in (
            "dcc_signing_key", "dcc_signing_certificate", "dcc_trusted_certificate"))

    def set_dcc_signing_paths(self, key_file: str, cert_file: str, trusted_file: str) -> None:
        for name, value in zip(("dcc_signing_key", "dcc_signing_certificate",
                                "dcc_trusted_certificate"), (key_file, cert_file, trusted_file),
                               strict=True):
            self.dcc_signing[name].setText(value)

    def metadata(self) -> CertificateMetadata:
        """The entered metadata. Raises MetadataError, with every bad field marked at once."""
        meta, problems = CertificateMetadata.from_dict_lenient(self.raw_values())
        if problems:
            self.show_problems(problems)
            first = next(iter(problems.values()))
            more = (tr(" (and {count} more, marked red)").format(count=len(problems) - 1)
                    if len(problems) > 1 else "")
            raise MetadataError(first + more)
        return meta

    def show_problems(self, problems: dict[str, str], raw: dict | None = None) -> None:
        """Mark every field in ``problems``; ``raw`` puts back the stored text of fields
        that could not be read, so what was typed is not lost."""
        for key, value in (raw or {}).items():
            if key in self.fields and key in problems and isinstance(value, str | int | float):
                self.fields[key].setText(str(value))
        for key, message in problems.items():
            if "standards[" in key:  # a stored standard left out: not in the table to mark
                continue
            self._mark(message)
        self.error_label.setStyleSheet("color: #b00020;")
        self.error_label.setText("\n".join(translated(m) for m in problems.values()))

    def _mark(self, message: str) -> None:
        self.error_label.setStyleSheet("color: #b00020;")
        self.error_label.setText(message)
        match = re.search(r"'(\w+)(?:\[(\d+)\]\.(\w+))?'", message)
        if not match:
            return
        if match.group(2):
            row, key = int(match.group(2)) - 1, match.group(3)
            if key in _STANDARD_COLUMNS and row < self.standards.rowCount():
                item = self.standards.item(row, _STANDARD_COLUMNS.index(key))
                if item is not None:
                    item.setBackground(Qt.GlobalColor.red)
                    self.details_area.ensureWidgetVisible(self.standards)
            return
        edit = self.fields.get(match.group(1))
        if edit is not None:
            edit.setStyleSheet(_ERROR_STYLE)
            edit.setFocus()
            self.details_area.ensureWidgetVisible(edit)

    def _timezone_checked(self) -> str | None:
        """The time zone typed (empty: the system's); None, marked, when it is not known."""
        from models.register.store import RegisterError, lab_timezone

        name = self.timezone.text().strip()
        if name:
            try:
                lab_timezone(name)
            except RegisterError as exc:
                self.timezone.setStyleSheet(_ERROR_STYLE)
                self.error_label.setStyleSheet("color: #b00020;")
                self.error_label.setText(explained(exc))
                self.details_area.ensureWidgetVisible(self.timezone)
                return None
        return name

    def accept(self) -> None:  # the dialog stays open on a bad field
        try:
            self.metadata()
        except MetadataError:
            return
        zone = self._timezone_checked()
        if zone is None:
            return
        self.lab_timezone_set.emit(zone)
        super().accept()

    def _save_lab_defaults(self) -> None:
        try:
            meta = self.metadata()
        except MetadataError:
            return
        zone = self._timezone_checked()
        if zone is None:
            return
        self.lab_timezone_set.emit(zone)
        self.lab_defaults_saved.emit(meta.lab_defaults())
        self.saved_details = meta
        self.error_label.setStyleSheet("color: #1b5e20;")
        # said what became a default and what did not (rev62day F15: no confirmation)
        self.error_label.setText(tr(
            "Saved as the lab's defaults: the laboratory, number scheme, reference "
            "standards, people, decision rule and this workbench's test plan. The customer, "
            "item, dates, language and tolerance are this certificate's, not defaults: they "
            "are kept with the project's details, also if you cancel now."))
