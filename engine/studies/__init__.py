"""Design studies: plan the points, evaluate them in chunks (in process or on Dask), summarise."""
