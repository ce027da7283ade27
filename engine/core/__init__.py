"""How a model is declared (spec), run (runner), swept (points) and cited (sources, equations)."""
