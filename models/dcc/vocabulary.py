"""The names AngleBench's digital calibration certificates (PTB DCC 3.3.0, D-SI 2.2.1) use:
namespaces, the schema version and the refTypes. The writer (DCC out) and the reader (DCC in:
a polygon's face deviations, a standard's certificate) both import them from here, so a
document AngleBench writes is one AngleBench reads.

refTypes: PTB's published basic ones where a notion has one (``basic_nominalValue``,
``basic_measuredValue``, ``basic_measurementError``, ``basic_referenceValue``); the project's
own carry the prefix ``anglebench_`` and are declared in the document's
``dcc:refTypeDefinitions`` under :data:`ANGLEBENCH_REFTYPE_NAMESPACE` (a placeholder URL under
the reserved ``example`` domain until the laboratory publishes its own).
"""

from __future__ import annotations

DCC_NAMESPACE = "https://ptb.de/dcc"
DCC_PREFIX = "dcc"
SI_NAMESPACE = "https://ptb.de/si"
SI_PREFIX = "si"
DS_NAMESPACE = "http://www.w3.org/2000/09/xmldsig#"
SCHEMA_VERSION = "3.3.0"
NSMAP = {DCC_PREFIX: DCC_NAMESPACE, SI_PREFIX: SI_NAMESPACE}

ANGLEBENCH_REFTYPE_NAMESPACE = "https://anglebench.example/dcc/reftypes"
ANGLEBENCH_REFTYPE_PREFIX = "anglebench_"
ANGLEBENCH_REFTYPE_RELEASE = "1"

# PTB's published basic refTypes (DCC refType list, "basic" namespace)
PTB_NOMINAL_VALUE = "basic_nominalValue"
PTB_MEASURED_VALUE = "basic_measuredValue"
PTB_MEASUREMENT_ERROR = "basic_measurementError"
PTB_REFERENCE_VALUE = "basic_referenceValue"

# Polygon face deviations: the cross-calibration workbench's polygon result (the polygon
# calibrated: what the polygon reader takes). One dcc:result of this refType holding a
# dcc:list with the two quantities below; the face count is the lists' length.
REFTYPE_POLYGON_FACE_DEVIATIONS = "anglebench_polygonFaceDeviations"
# A reference polygon's face deviations, in the same form: the polygon workbench's (an
# encoder calibrated against that polygon) as the polygon's own certificate states them.
# Not a result of this calibration and not the item's: the polygon reader never takes it.
# Up to 0.8.11 written as anglebench_polygonFaceDeviations, under the name below.
REFTYPE_REFERENCE_POLYGON_FACE_DEVIATIONS = "anglebench_referencePolygonFaceDeviations"
#: the name (en, zh) of that result, the same in every version that wrote it (0.4 to 0.8.11;
#: en always, the mandatory language): how a document of 0.8.11 or before tells it apart
REFERENCE_POLYGON_RESULT_NAMES = (
    "Reference polygon face deviations (from face 1, as its certificate states them)",
    "参考多面棱体各面偏差（相对第 1 面，按其校准证书给出）")
#: the polygon workbench's title (en, zh): a measurementResult of that name calibrates an
#: encoder against a reference polygon
POLYGON_ENCODER_TEST_NAMES = ("Polygon encoder test", "多面棱体编码器检测")
REFTYPE_FACE_INDEX = "anglebench_faceIndex"  # si:realListXMLList 1..N, unit \one
REFTYPE_FACE_DEVIATION = "anglebench_faceDeviation"  # \arcsecond, with si:expandedMUXMLList
FACE_INDEX_UNIT = r"\one"
FACE_DEVIATION_UNIT = r"\arcsecond"

# The project's own refTypes (declared in dcc:refTypeDefinitions of every document)
REFTYPE_CALIBRATION_CERTIFICATE = "anglebench_calibrationCertificate"
REFTYPE_TEST_REPORT = "anglebench_testReport"
REFTYPE_NOT_A_CALIBRATION = "anglebench_notACalibration"
#: a specimen (the bundled example details, the window's training switch): not a certificate,
#: in no register; it takes the place of the calibration certificate's statement
REFTYPE_SPECIMEN = "anglebench_specimen"
REFTYPE_CONFORMITY = "anglebench_conformity"
REFTYPE_TRACEABILITY = "anglebench_traceability"
REFTYPE_MEASURAND = "anglebench_measurand"
REFTYPE_VALIDITY = "anglebench_validity"
REFTYPE_ISSUED_PDF = "anglebench_issuedPdf"
REFTYPE_SETUP_PARAMETERS = "anglebench_setupParameters"
REFTYPE_SUMMARY = "anglebench_summary"
REFTYPE_BUDGET = "anglebench_uncertaintyBudget"
REFTYPE_CURVE = "anglebench_curve"
#: a standard's error as the budget takes it, 0, with its stated uncertainty in D-SI form
#: (written as "anglebench_standardExpandedUncertainty", the figure alone, up to 0.8.10)
REFTYPE_STANDARD_U = "anglebench_standardStatedUncertainty"
REFTYPE_STANDARD_DUE = "anglebench_standardDueDate"
REFTYPE_CERTIFICATE_ID = "anglebench_certificateId"
REFTYPE_TEMPERATURE = "anglebench_temperature"
REFTYPE_OPERATOR = "anglebench_operator"
REFTYPE_APPROVER = "anglebench_approver"
#: on a per-point quantity whose U the laboratory's CMC holds: a dcc:metaData whose
#: validXMLList marks the points where U is the CMC (the budget gave less)
REFTYPE_U_RAISED_TO_CMC = "anglebench_uncertaintyRaisedToCmc"
#: a statement: an original issued as a calibration of its own, separate from certificates
#: of the same item and date of calibration that stay valid (their numbers its references)
REFTYPE_SEPARATE_CALIBRATION = "anglebench_separateCalibration"
#: an original issued in place of withdrawn certificates of the same calibration
REFTYPE_IN_PLACE_OF_WITHDRAWN = "anglebench_inPlaceOfWithdrawn"
#: the readings are those of a certificate of another item, the user said why (hostile78 F7)
REFTYPE_READINGS_OF_ANOTHER_ITEM = "anglebench_readingsOfAnotherItem"
#: a statement: what an amendment or replacement changed of the certificate it supersedes,
#: a confirmed corrected serial number or date of calibration first (ISO/IEC 17025 7.8.8.2;
#: coreData/reportAmendedSubstituted names the certificate, and has no room for why)
REFTYPE_REVISION = "anglebench_revision"

LANGUAGES = ("en", "zh")
MANDATORY_LANGUAGES = ("en",)
