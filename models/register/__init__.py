"""The certificate register: unique numbers across a lab, the technical record behind every
issued certificate, amendments and each instrument's history (SQLite or PostgreSQL)."""
