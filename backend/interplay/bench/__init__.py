"""Speed benchmarks (`interplay bench`): the API, SPAM, CODA and the ARFlow reactor."""
