"""The fringe workbench's signal tolerance and interpolator table on the command line
(#45): its options, what they ask for, and what they add to the JSON and the summary.
Declared here, in the workbench's own folder, and reached by app/cli.py through the
JudgesSignals capability (models/workbench.py)."""

from __future__ import annotations

import argparse
import dataclasses
import math
from pathlib import Path
from typing import Any

from models.messages import QT_TR_NOOP, message, separated


def add_arguments(p: argparse.ArgumentParser, words) -> None:
    """The fringe workbench's signal tolerance and interpolator table options (#45)."""
    p.add_argument("--signal-preset", metavar="KEY",
                   help=words(QT_TR_NOOP("fringe: judge the signals (amplitudes, ratio, phase, "
                                         "offsets) against a tolerance preset, e.g. "
                                         "heidenhain_1vpp; a mounting indication, not a "
                                         "statement of conformity (JSON: signal_tolerance)")))
    p.add_argument("--signal-presets", metavar="PRESETS.json",
                   help=words(QT_TR_NOOP("fringe: the lab's own presets (a list of presets, or "
                                         "lab defaults holding signal_tolerance_presets)")))
    p.add_argument("--signal-scale", metavar="SCALE", type=float, default=1.0,
                   help=words(QT_TR_NOOP("fringe: the preset's unit per unit of the record (V "
                                         "per ADC count, µA per V); default 1")))
    p.add_argument("--signal-window", metavar="PERIODS", type=int,
                   help=words(QT_TR_NOOP("fringe: periods a window of the signal quality along "
                                         "the record (default: at most 1000 windows)")))
    p.add_argument("--interpolator-table", metavar="OUT.csv|OUT.h|OUT.hex",
                   help=words(QT_TR_NOOP("fringe: also write an interpolator look-up table as a "
                                         "chip takes it (CSV, C header or Intel HEX), with its "
                                         "residual predicted after quantisation")))
    p.add_argument("--table-chip", choices=("generic", "ic-tw8"), default="generic",
                   help=words(QT_TR_NOOP("the interpolator's profile (ic-tw8: 64 entries of 8 "
                                         "bits, modelled after iC-Haus iC-TW8)")))
    p.add_argument("--table-entries", metavar="N", type=int,
                   help=words(QT_TR_NOOP("entries of the interpolator table, 2^k (generic: "
                                         "default 64)")))
    p.add_argument("--table-bits", metavar="B", type=int,
                   help=words(QT_TR_NOOP("bits of its signed codes (generic: default 8)")))
    p.add_argument("--table-lsb", metavar="FRACTION", type=float,
                   help=words(QT_TR_NOOP("one code step as a fraction of a period (generic: "
                                         "default the smallest power of two holding the "
                                         "table)")))
    p.add_argument("--table-interpolation", choices=("step", "linear"),
                   help=words(QT_TR_NOOP("generic: the entry below the measured phase (step, "
                                         "default) or linear between two entries")))
    p.add_argument("--table-terms", metavar="offset,gain,phase",
                   help=words(QT_TR_NOOP("generic: corrected apart from the table (written "
                                         "beside it): any of offset, gain, phase")))
    p.add_argument("--table-max-residual", metavar="X", type=float,
                   help=words(QT_TR_NOOP("refuse the table when its predicted residual (largest "
                                         "magnitude) exceeds X, in the error's unit (arcsec, or "
                                         "nm for an interferometer)")))


FLAGS = ("signal_preset", "signal_presets", "signal_window", "interpolator_table",
                 "table_entries", "table_bits", "table_lsb", "table_interpolation",
                 "table_terms", "table_max_residual")


def setup(args: argparse.Namespace):
    """The preset and the table profile asked for (None when not); a message when the
    options do not hold (raised as ValueError)."""
    from models.fringe.signal_tolerance import (
        BUILTIN_PRESETS,
        LAB_DEFAULTS_KEY,
        load_presets,
        preset_by_key,
    )

    presets = list(BUILTIN_PRESETS)
    if args.signal_presets:
        import json  # only for a presets file

        try:
            with open(args.signal_presets, encoding="utf-8-sig") as handle:
                stored = json.load(handle)
        except (OSError, ValueError) as exc:
            raise ValueError(message(QT_TR_NOOP("{path}: cannot read the presets ({reason})"),
                                     path=args.signal_presets, reason=str(exc))) from None
        lab = stored if isinstance(stored, dict) else {LAB_DEFAULTS_KEY: stored}
        presets, problems = load_presets(lab)
        if problems:
            raise ValueError(message("{path}: {reason}", path=args.signal_presets,
                                     reason=problems[0]))
    preset = preset_by_key(args.signal_preset, presets) if args.signal_preset else None
    if not (math.isfinite(args.signal_scale) and args.signal_scale > 0):
        raise ValueError(message(QT_TR_NOOP("--signal-scale: must be a positive number, not "
                                            "{scale}"), scale=f"{args.signal_scale:g}"))
    if args.signal_window is not None and args.signal_window < 1:
        raise ValueError(message(QT_TR_NOOP("--signal-window: at least one period, not {n}"),
                                 n=args.signal_window))
    profile = None
    if args.interpolator_table:
        # the table's modules (the writer's: its atomic write's tempfile) only when a table is
        # asked for
        from models.fringe.interpolator_export import FORMATS
        from models.fringe.interpolator_table import chip_profile

        if Path(args.interpolator_table).suffix.lower() not in FORMATS:
            raise ValueError(message(QT_TR_NOOP("--interpolator-table: {path}: write .csv, .h or "
                                                ".hex"), path=args.interpolator_table))
        terms = None
        if args.table_terms is not None:
            terms = tuple(t.strip() for t in args.table_terms.split(",") if t.strip())
        profile = chip_profile(args.table_chip, args.table_entries, args.table_bits,
                               args.table_lsb, terms)
        if args.table_interpolation and args.table_chip == "generic":
            profile = dataclasses.replace(profile, interpolation=args.table_interpolation)
        elif args.table_interpolation and args.table_interpolation != profile.interpolation:
            raise ValueError(message(QT_TR_NOOP("--table-interpolation: the {chip} interpolates "
                                                "{how}"), chip=profile.name,
                                     how=profile.interpolation))
    elif any(getattr(args, f) is not None for f in FLAGS if f.startswith("table_")):
        raise ValueError(message(QT_TR_NOOP("the --table-… options shape the interpolator "
                                            "table: give --interpolator-table OUT too")))
    return preset, profile


def results(args, result, preset, profile):
    """(the JSON keys to add, the summary lines, the table or None) of the fringe options."""
    from models.fringe.signal_quality import default_window, signal_quality, tolerance_json
    from models.fringe.signal_tolerance import NOT_CONFORMITY, judge, signal_figures

    keys: dict[str, Any] = {}
    texts: list[Any] = []
    table = None
    window = args.signal_window or default_window(result)
    if preset is not None:
        figures = signal_figures(result, preset, args.signal_scale)
        quality = signal_quality(result, preset, args.signal_scale, window)
        keys["signal_quality"] = quality.windows
        keys["signal_quality_units"] = quality.units
        keys["signal_tolerance"] = tolerance_json(figures, preset, args.signal_scale, quality)
        texts.append(message(QT_TR_NOOP("Signals against {preset}:"), preset=preset.name))
        for j in judge(figures, preset):
            band = j.band
            outer = (message(QT_TR_NOOP(", outer {low} … {high}"), low=f"{band.outer[0]:.4g}",
                             high=f"{band.outer[1]:.4g}") if band.outer else "")
            texts.append(message(QT_TR_NOOP("  {quantity} = {value}{unit}: {state} (band {low} "
                                            "… {high}{outer})"),
                                 quantity=j.quantity, value=f"{j.value:.4g}",
                                 unit=f" {j.unit}" if j.unit else "",
                                 state=message(STATE_TEXT[j.state]),
                                 low=f"{band.inside[0]:.4g}", high=f"{band.inside[1]:.4g}",
                                 outer=outer))
        texts += quality.summary()
        texts.append(NOT_CONFORMITY)
    elif args.signal_window is not None:
        quality = signal_quality(result, None, args.signal_scale, window)
        keys["signal_quality"] = quality.windows
        keys["signal_quality_units"] = quality.units
    if profile is not None:
        from models.fringe.interpolator_table import design_table

        period = result.period_length
        asked = (None if args.table_max_residual is None
                 else args.table_max_residual / period)
        table = design_table(result, profile, asked, (period, result.unit))
        keys["interpolator_table"] = {
            "profile": profile.key, "entries": table.entries, "bits": profile.bits,
            "lsb_period": table.lsb_period, "interpolation": profile.interpolation,
            "sign": profile.sign, "separate_terms": list(table.terms.applied),
            "codes": table.codes.tolist(), "file": args.interpolator_table,
            "predicted_residual": table.residual.as_dict(period, result.unit),
            "residual_unquantised": table.residual_unquantised.as_dict(period, result.unit),
            "error_without_table": table.residual_without.as_dict(period, result.unit),
            "source": profile.source}
    return keys, texts, table


STATE_TEXT = {"inside": QT_TR_NOOP("inside"), "outer": QT_TR_NOOP("in the outer band"),
              "outside": QT_TR_NOOP("outside")}


#: said after the caveat where orders fold and the table is written as Intel HEX, which has
#: no comments to carry it (the CSV's and the C header's comments do)
HEX_HAS_NO_CAVEAT = QT_TR_NOOP(
    "Intel HEX has no comments, so the file itself does not say where the table holds: "
    "keep this note with it")


def write_table(args, result, table):
    """Write the interpolator table asked for (OSError when it cannot be) and say what was
    written."""
    from models.fringe.compensation_at_samples import compensation_caveat
    from models.fringe.interpolator_export import write_interpolator_table

    # where orders fold, the predicted residual is the fitted signals', which hold orders
    # not fitted: it holds at the sampled phases only (day review 68 F8), said in the file
    # too (its comments) and on the command's line
    caveat = compensation_caveat(result)
    write_interpolator_table(args.interpolator_table, table, Path(args.file).name,
                             result.period_length, result.unit, caveat=str(caveat))
    r, period, unit = table.residual, result.period_length, result.unit
    written = message(QT_TR_NOOP(
        "Interpolator table ({chip}, {entries} entries of {bits} bits, LSB {lsb} of a "
        "period) written to {path}: predicted residual {worst} {unit} largest, {rms} {unit} "
        "RMS (the entries alone {ideal} {unit}; without a table {without} {unit})"),
        chip=table.profile.key, entries=table.entries,
        bits=table.profile.bits, lsb=f"{table.lsb_period:.4g}",
        path=args.interpolator_table, worst=f"{r.max_abs * period:.4g}",
        rms=f"{r.rms * period:.4g}",
        ideal=f"{table.residual_unquantised.max_abs * period:.4g}",
        without=f"{table.residual_without.max_abs * period:.4g}", unit=unit)
    if not caveat:
        return written
    if Path(args.interpolator_table).suffix.lower() == ".hex":  # no comment syntax: this
        # line is the only place the caveat is said (the CSV's and the C header's carry it)
        return separated([written, caveat, message(HEX_HAS_NO_CAVEAT)], "; ")
    return separated([written, caveat], "; ")
