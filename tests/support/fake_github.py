"""GitHub's REST API as a Classroom grade meets it (tools/classroom/report --notify), served on
127.0.0.1 so the tests can run the workflow's last step: the workflow run, its check suite's check
runs, and the update of one, each answered as GitHub documents it and every update kept."""
import json
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

TOKEN = "fake-token"


class FakeGitHub:
    def __init__(self, check_runs=(("Autograding Tests", 99),), repository="student/pathlab", run_id=42, suite=7):
        self.repository, self.run_id, self.suite = repository, run_id, suite
        self.check_runs = [{"id": i, "name": name} for name, i in check_runs]
        self.updates = []  # (check run id, the body posted)
        fake = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args):
                pass

            def answer(self, code, body):
                data = json.dumps(body).encode()
                self.send_response(code)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

            def route(self, method):
                if self.headers.get("Authorization") != f"Bearer {TOKEN}":
                    return self.answer(401, {"message": "Bad credentials"})
                base = f"/repos/{fake.repository}"
                path = self.path.split("?", 1)[0]
                if method == "GET" and path == f"{base}/actions/runs/{fake.run_id}":
                    return self.answer(200, {"id": fake.run_id, "check_suite_id": fake.suite,
                                             "check_suite_url": f"https://api.github.com{base}/check-suites/{fake.suite}"})
                if method == "GET" and path == f"{base}/check-suites/{fake.suite}/check-runs":
                    return self.answer(200, {"total_count": len(fake.check_runs), "check_runs": fake.check_runs})
                for run in fake.check_runs:
                    if method == "PATCH" and path == f"{base}/check-runs/{run['id']}":
                        length = int(self.headers.get("Content-Length", "0"))
                        fake.updates.append((run["id"], json.loads(self.rfile.read(length))))
                        return self.answer(200, {"id": run["id"], "name": run["name"]})
                return self.answer(404, {"message": "Not Found"})

            def do_GET(self):
                self.route("GET")

            def do_PATCH(self):
                self.route("PATCH")

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)

    def __enter__(self):
        threading.Thread(target=self.server.serve_forever, daemon=True).start()
        return self

    def __exit__(self, *exc):
        self.server.shutdown()
        self.server.server_close()

    def env(self) -> dict:
        """What GitHub Actions sets for a step, pointed at this server."""
        return {"GITHUB_API_URL": f"http://127.0.0.1:{self.server.server_port}", "GITHUB_TOKEN": TOKEN,
                "GITHUB_REPOSITORY": self.repository, "GITHUB_RUN_ID": str(self.run_id),
                "GITHUB_JOB": "run-autograding-tests"}

    def points(self) -> list:
        """Each update's "Points X/Y", as its summary and its annotation say it (both must agree)."""
        said = []
        for _, body in self.updates:
            output = body.get("output", {})
            notes = [a.get("message") for a in output.get("annotations", [])]
            said.append(output.get("summary") if notes == [output.get("summary")] else f"disagree: {output}")
        return said
