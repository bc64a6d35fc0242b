"""What a job runs in its worker thread: generation and reaction runners."""
