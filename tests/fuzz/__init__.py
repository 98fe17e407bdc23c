"""The fuzz suite's machinery: inputs (strategies, mutations) and the harness that runs
each input through ``mechloop check`` and ``mechloop solve`` and judges the outcome."""
