"""Day review 74 F15: the polygon's "Certificate … issued" stayed in the status bar of the
Fringe tab, though a workbench's status message is shown on its own tab only (the window's
guide). A certificate's message — what the certificate presenter says through the window's
certificate dialogs when it issues, writes a draft or results — is the message of the
workbench in front, whose certificate it is: put aside on another tab, shown again on its
own for the time it had left."""

from __future__ import annotations

from tests.app.capture.window_steps import show_workbench as _show

ISSUED = ("Certificate AB-2026-0009 issued: written to /tmp/C_polygon.pdf and recorded in the "
          "register")


def test_a_certificates_message_stays_on_its_workbenchs_tab(window):
    _show(window, "polygon")
    window.certificates.view.show_status(ISSUED, 60_000)
    bar = window.statusBar()
    assert bar.currentMessage() == ISSUED
    _show(window, "fringe")
    assert bar.currentMessage() == ""
    _show(window, "positioning")
    assert bar.currentMessage() == ""
    _show(window, "polygon")
    assert bar.currentMessage() == ISSUED
