"""pytest-benchmark suite for ancf-bench (run with ``make bench``; summarise with
``python -m benchmarks.summarize``)."""
