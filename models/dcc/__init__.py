"""PTB digital calibration certificates (DCC 3.3.0): vocabulary, schema validation, writer."""
