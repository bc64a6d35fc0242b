"""Building the processed data set (models/data) from the raw captures in ../shared/data."""
