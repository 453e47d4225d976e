"""The files a user takes away: the certificate as a PDF, and its results as CSV or XLSX."""
