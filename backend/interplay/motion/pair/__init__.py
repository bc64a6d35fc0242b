"""Two people: the 45-sphere body, CODA's interaction geometry, two-person training windows, and pairs composed from real single-person clips."""
