"""HTTP routes (thin: validation in schemas, work in jobs/store)."""
