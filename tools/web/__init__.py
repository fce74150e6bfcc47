"""The web build: the web preset compiled with Emscripten and its programs run under Node.js (docs/web.md)."""
