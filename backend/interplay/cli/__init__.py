"""The `interplay` command: one module per command group; it runs the pipeline and never imports the web layer (only `serve` builds the app)."""
