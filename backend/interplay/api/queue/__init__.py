"""The job queue behind `api/jobs.py`: in-memory live jobs (`live`), the batched writer of their
events and ends to the database (`writer`), stored jobs a stream follows from the database
(`follow`), what running one job means (`execute`), and the procrastinate queue and worker
used with PostgreSQL (`engine`)."""
