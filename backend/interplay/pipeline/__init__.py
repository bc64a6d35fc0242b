"""The job pipeline the API and the CLI both call: plan → generate → review → trajectory, and editing a stored motion."""
