"""Polygon encoder test workbench: the presenter (no widgets: it asks its view)."""

from __future__ import annotations

import datetime as dt
from collections.abc import Callable
from pathlib import Path

from models.messages import QT_TR_NOOP, message
from models.polygon import plots
from models.polygon.analysis import POLYGON
from models.polygon.certificate_reader import read_polygon_certificate
from models.polygon.model import GRADE_ACCURACY_ARCSEC, PolygonResult
from models.project.file import WorkbenchState
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import TableImportError
from widgets.i18n import declared, explained, tr, translated
from widgets.polygon.view import PolygonView
from widgets.table_commands import KeptValueCommand
from widgets.workbench_presenter import AwaitedColumn, WorkbenchPresenter


def _face_list(faces: list[int]) -> str:
    """"1–6", "2, 5, 7–9": runs of consecutive faces joined."""
    runs: list[list[int]] = []
    for face in faces:
        if runs and face == runs[-1][-1] + 1:
            runs[-1].append(face)
        else:
            runs.append([face])
    return ", ".join(f"{r[0]}–{r[-1]}" if len(r) > 2 else ", ".join(map(str, r)) for r in runs)


class PolygonPresenter(WorkbenchPresenter):
    """Error per face, closure check and pyramidal correction on every edit."""

    view_class = PolygonView

    def __init__(self, view: PolygonView | None = None, parent=None) -> None:
        super().__init__(POLYGON, view, parent)
        #: the window adds a polygon read from its DCC (a PolygonReference) to this
        #: workbench's standards (its U enters the budget as a polygon certificate's does);
        #: returns what to say
        self.reference_standard_found: Callable[[object], tuple] = lambda _reference: ()
        #: the same, checked and stored nowhere (DccError: another polygon's; MetadataError:
        #: a standard the details cannot take): before anything of the DCC is applied
        self.reference_standard_checked: Callable[[object], tuple] = lambda _reference: ()
        #: the folder of the DCC schemas a DCC is validated against ("": not validated)
        self.dcc_schema_dir: Callable[[], str] = lambda: ""
        #: the lab's trusted certificate for a DCC's signature (a path; "": the environment's)
        self.dcc_trusted_certificate: Callable[[], str] = lambda: ""
        # the register a DCC of this lab's own is checked against ("": none; hostile78 F4)
        self.dcc_register_url: Callable[[], str] = lambda: ""
        #: what the last certificate loaded said beside its values (a DCC's notes, the
        #: deviation column's values replaced)
        self.certificate_notes: list[str] = []
        #: the polygon certificate's deviations by face as last loaded (the cell's text), for
        #: the faces not yet in the table: a take of such a face fills its row's deviation
        #: (app/capture/panel.py _from_reference). live78: loaded before a live run (the
        #: table empty), the certificate changed no cell and was dropped without a word;
        #: every face taken then had no deviation, its row could not be read, and the run
        #: showed no result and no faces. Saved with the project (WorkbenchState.
        #: certificate_by_face), another project's taken when one is opened or a new one
        #: begun (load_state): another day's polygon may be another one. A row typed with
        #: a face and its reading gets it too (:meth:`_deviation_cells`, gui78).
        self.face_deviations: dict[int, str] = {}
        self.table_model.cells_brought = self._deviation_cells
        self.table_model.rows_brought = self._deviation_rows

    def show_result(self, result: PolygonResult) -> None:
        self.table_model.set_highlight_rows(result.closure_rows)
        tolerance = GRADE_ACCURACY_ARCSEC.get(result.grade)
        self.view.show_figures(*self.in_unit(
            plots.error_figure(result), plots.residual_figure(result),
            plots.tilt_figure(result), plots.harmonics_figure(result)),
            sets=self.in_unit(plots.sets_figure(result, self.parsed, tolerance))[0])
        if not result.valid:
            self.view.append_to_readings_caption(tr(" — RUN INVALID (closure failed)"))

    def awaited_column(self, sheet: ReadingsSheet) -> AwaitedColumn | None:
        """The deviation column while no row has a face deviation that reads and no
        certificate is kept by face (:attr:`face_deviations`), with readings in the table:
        every row needs its face's deviation from the polygon's certificate (SPEC §2,
        b_i = (i − 1)·360°/n + dev_i); a blank one is never taken as 0, which would take
        the polygon as perfect and put its face deviations into the encoder's errors on the
        certificate. Said once, not as a bad cell in every row (plan80: captured rows showed
        "0 used, 24 bad cells" as if each deviation had been typed wrong)."""
        if self.face_deviations:
            return None
        dev = sheet.column_index("polygon_dev_arcsec")
        column = sheet.columns[dev]
        readings = [sheet.column_index(k) for k in self.kind.plan_reading_keys]
        if not any(sheet.text(r, c).strip() for r in range(sheet.row_count) for c in readings):
            return None
        for r in range(sheet.row_count):
            text = sheet.text(r, dev)
            if text.strip():
                try:
                    column.parse(text)
                except ValueError:
                    continue  # typed wrong: that cell stays red, the column still awaited
                return None
        return AwaitedColumn("polygon_dev_arcsec", tr(
            "the polygon's face deviations are missing: load its certificate (“Load polygon "
            "certificate…”, at the end of the set-up) or type them in the {column} column. A "
            "blank one is not taken as 0; the readings are kept.").format(
                # its header as the table shows it ("棱体偏差 [\"]"): the title alone has no
                # translation, and the Chinese sentence named an English "polygon dev" column
                # the table has not (gui80)
                column=declared(column.header)),
            # the readings' caption: "Readings — 24 taken, waiting for the face deviations"
            # (live81: "0 used" beside the readings read as readings thrown away)
            tr("waiting for the face deviations"))

    def load_certificate_dialog(self) -> None:
        from models.certificate.metadata import MetadataError
        from models.dcc.reader import DccError
        from models.dcc.signature import SigningError

        path = self.view.ask_certificate_file()
        if path:
            try:
                self.load_certificate(path)
            except (TableImportError, DccError, SigningError, MetadataError) as exc:
                self.view.tell(tr("Cannot read certificate"), explained(exc))
                return
            if self.certificate_notes:
                self.view.tell(tr("Polygon certificate"), "\n".join(self.certificate_notes))

    def load_certificate(self, path: str) -> int:
        """Fill the deviation column by position (one undo step); returns the cells changed.
        A .xml file is the polygon's digital calibration certificate (DCC): its deviations
        replace the column's, and the polygon with its U joins the certificate's standards.

        Raises TableImportError for a bad file and when a position has no deviation;
        DccError for a DCC refused (the reason named).
        """
        self.certificate_notes = []
        if str(path).lower().endswith(".xml"):
            return self._load_dcc(str(path))
        return self._fill_deviations(read_polygon_certificate(path), tr("Load polygon certificate"),
                                     str(path))

    def _load_dcc(self, path: str) -> int:
        from models.dcc.reader import DccError, read_polygon_dcc
        from models.dcc.signature import signature_demanded, trusted_certificate
        from models.register.read_in import own_dcc_refusal_at

        details = self.certificate_details()
        when = getattr(details, "calibration_date", "") or dt.date.today().isoformat()
        faces = int(self.settings.get("faces") or 0) or max(self._positions()) or None
        # this register's own DCC: read as issued, and while current (hostile78 F4)
        refused = own_dcc_refusal_at(self.dcc_register_url(), path) \
            if self.dcc_register_url() else None
        if refused is not None:
            raise DccError(refused)
        reference = read_polygon_dcc(path, self.dcc_schema_dir() or None, measurement_date=when,
                                     faces=faces,
                                     trusted_cert=trusted_certificate(self.dcc_trusted_certificate()),
                                     trust_named=signature_demanded(
                                         self.dcc_trusted_certificate()))
        # everything checked before anything changes: the polygon the details list is the
        # DCC's, and its standard one they take (U, k); then the column and the standard
        placed = tuple(self.reference_standard_checked(reference))
        column = self.sheet.column_index("polygon_dev_arcsec")
        position_column = self.sheet.column_index("position")
        differed = False
        for row in range(self.sheet.row_count):
            before = self.sheet.text(row, column).strip()
            try:
                position = int(float(self.sheet.text(row, position_column)))
            except ValueError:
                continue
            if before and position in reference.deviations:
                try:
                    differed = differed or abs(float(before) - reference.deviations[position]) > 5e-4
                except ValueError:
                    differed = True
        changed = self._fill_deviations(reference.deviations, tr("Load polygon certificate"),
                                        path, ".6f")
        placed = tuple(self.reference_standard_found(reference) or placed)
        notes = [translated(n) for n in (*reference.notes, *placed)]
        if differed:
            notes.insert(0, translated(message(QT_TR_NOOP(
                "the deviation column held other values: they were replaced by those of "
                "certificate {id} ({path})"), id=reference.certificate_id, path=path)))
        self.certificate_notes = notes
        return changed

    def accept_reference(self, reference) -> int:
        """The face deviations another workbench sends (models.workbench.SentReference, from
        face 1) in the deviation column by position, one undo step; an empty table gets a row
        per face. ValueError, nothing changed, when a position has none."""
        label = tr("Reference from another workbench")
        if not any(self.sheet.text(r, self.sheet.column_index("position")).strip()
                   for r in range(self.sheet.row_count)):
            column = self.sheet.column_index("polygon_dev_arcsec")
            rows = []
            for position, value in sorted(reference.values.items()):
                row = [""] * self.sheet.column_count
                row[self.sheet.column_index("position")] = str(position)
                row[column] = f"{value:.6f}"
                rows.append(row)
            self.table_model.replace_all(rows, label)
            return len(rows)
        try:
            return self._fill_deviations(reference.values, label, declared(reference.kind), ".6f")
        except TableImportError as exc:
            raise ValueError(str(exc)) from None

    def held_reference(self) -> dict[int, float]:
        """The deviation column by position as it holds now (cells that do not read left
        out): what a sent reference is compared with (app/reference_sender.py)."""
        column = self.sheet.column_index("polygon_dev_arcsec")
        position_column = self.sheet.column_index("position")
        out: dict[int, float] = {}
        for row in range(self.sheet.row_count):
            try:
                out[int(float(self.sheet.text(row, position_column)))] = float(
                    self.sheet.text(row, column))
            except ValueError:
                continue
        return out

    def _fill_deviations(self, deviations: dict[int, float], label: str, path: str,
                         spec: str = "g") -> int:
        column = self.sheet.column_index("polygon_dev_arcsec")
        position_column = self.sheet.column_index("position")
        changes = []
        for row in range(self.sheet.row_count):
            text = self.sheet.text(row, position_column).strip()
            if not text:
                continue
            try:
                position = int(float(text))
            except ValueError:
                continue
            if position not in deviations:
                read = max(self._positions())
                # a polygon's own reference (faces 1…m, m ≥ 3) for another face count
                if (len(deviations) >= 3 and read != len(deviations)
                        and sorted(deviations) == list(range(1, len(deviations) + 1))):
                    raise TableImportError(message(QT_TR_NOOP(
                        "{path}: the readings have {read} faces (position {position}, row "
                        "{row}), the reference {faces}: {read} faces against {faces}; choose "
                        "the polygon's own reference"), path=str(path), read=read,
                        position=position, row=row + 1, faces=len(deviations)))
                raise TableImportError(message(QT_TR_NOOP(
                    "{path}: no deviation for position {position} (row {row} of the readings)"),
                    path=str(path), position=position, row=row + 1))
            changes.append((row, column, format(deviations[position], spec)))
        kept = {face: format(value, spec) for face, value in deviations.items()}
        # the cells and the deviations kept, one undo step: the project is changed by it
        # even when no row has a face yet, and saved with them (gui78)
        if kept == self.face_deviations:
            self.table_model.set_cells(changes, label)
        else:
            self.undo_stack.beginMacro(label)
            self.table_model.set_cells(changes, label)
            self.undo_stack.push(KeptValueCommand(self._keep_face_deviations,
                                                  self.face_deviations, kept, label))
            self.undo_stack.endMacro()
        in_table = set(self._positions())
        waiting = sorted(face for face in deviations if face not in in_table)
        if waiting:  # said: a certificate loaded before the run changes no cell
            self.view.show_status(tr("{path}: {count} face(s) have no row yet ({faces}); their "
                                     "deviations are filled in as each face is taken or "
                                     "typed").format(
                path=Path(path).name, count=len(waiting), faces=_face_list(waiting)))
        return len(changes)

    def _keep_face_deviations(self, kept: dict[int, str]) -> None:
        self.face_deviations = dict(kept)

    def _deviation_cells(self, changes: list[tuple[int, int, str]]
                         ) -> list[tuple[int, int, str]]:
        """The deviations an edit's rows get from the certificate kept by face (as a take
        gets its face's: app/capture/panel.py _from_reference): each row the edit touches
        that then has its face and a reading but a blank deviation, the edit not writing
        that cell — another row's deviation for the face if the table has one, else the
        certificate's. live78: a row typed by hand after the certificate was loaded on an
        empty table got none; red, and no result."""
        if not self.face_deviations:
            return []
        sheet = self.sheet
        dev, position = (sheet.column_index("polygon_dev_arcsec"),
                         sheet.column_index("position"))
        new = {(r, c): t for r, c, t in changes}

        def text(r: int, c: int) -> str:
            if (r, c) in new:
                return new[(r, c)].strip()
            return sheet.text(r, c).strip() if r < sheet.row_count else ""

        return self._kept_deviations(
            sorted({r for r, _, _ in changes}), text,
            lambda row: (row, dev) in new,
            lambda row, face: {sheet.text(r, dev).strip() for r in range(sheet.row_count)
                               if r != row and sheet.text(r, position).strip() == face
                               and sheet.text(r, dev).strip()})

    def _deviation_rows(self, rows: list[list[str]]) -> list[tuple[int, int, str]]:
        """The deviations pasted rows that replace the whole sheet get (Ctrl+A, Ctrl+V of a
        full set of readings), as :meth:`_deviation_cells` gives an edit's rows: each row
        with its face and a reading but no deviation, another pasted row's deviation for the
        face if one has it, else the certificate's kept by face."""
        if not self.face_deviations:
            return []
        sheet = self.sheet
        dev, position = (sheet.column_index("polygon_dev_arcsec"),
                         sheet.column_index("position"))

        def text(r: int, c: int) -> str:
            return rows[r][c].strip() if c < len(rows[r]) else ""

        return self._kept_deviations(
            range(len(rows)), text, lambda _row: False,
            lambda row, face: {text(r, dev) for r in range(len(rows))
                               if r != row and text(r, position) == face and text(r, dev)})

    def _kept_deviations(self, rows, text: Callable[[int, int], str],
                         written: Callable[[int], bool],
                         others: Callable[[int, str], set[str]]
                         ) -> list[tuple[int, int, str]]:
        """(row, deviation column, text) for each of ``rows`` that has its face and a
        reading but a blank deviation (``text``: a cell as the change leaves it) which the
        change does not write itself (``written``): the deviation the face's other rows
        have (``others``) where they agree, else the certificate's kept by face."""
        dev, position = (self.sheet.column_index("polygon_dev_arcsec"),
                         self.sheet.column_index("position"))
        readings = [self.sheet.column_index(k) for k in self.kind.plan_reading_keys]
        out = []
        for row in rows:
            face = text(row, position)
            if written(row) or text(row, dev) or not face.isdigit() \
                    or int(face) not in self.face_deviations \
                    or not any(text(row, c) for c in readings):
                continue
            known = others(row, face)
            # one deviation per face; two different ones are the technician's to settle
            if not known:
                known = {self.face_deviations[int(face)]}
            if len(known) == 1:
                out.append((row, dev, known.pop()))
        return out

    def state(self, deep: bool = True) -> WorkbenchState:
        state = super().state(deep)
        state.certificate_by_face = dict(self.face_deviations)
        return state

    def load_state(self, state: WorkbenchState, project: str = "") -> None:
        # another project's: its polygon may be another one (none kept: none)
        self.face_deviations = dict(state.certificate_by_face)
        super().load_state(state, project)

    def _positions(self) -> list[int]:
        """The face numbers in the position column (unreadable cells left out)."""
        column = self.sheet.column_index("position")
        out = []
        for row in range(self.sheet.row_count):
            try:
                out.append(int(float(self.sheet.text(row, column))))
            except ValueError:
                continue
        return out or [0]

    def clear_result(self) -> None:
        self.table_model.set_highlight_rows(set())
        self.view.clear_result()
        # no set complete yet (set 1 in progress): the faces read so far, not "No data"
        # (gui77: a technician judges the set-up from the first faces)
        if self.parsed is not None:
            (faces_read,) = self.in_unit(plots.faces_read_figure(self.parsed,
                                                                 self.result_settings))
            if faces_read is not None:
                self.view.show_faces_read(faces_read)
