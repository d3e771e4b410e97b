"""A client of `mbc lsp` for the tests and the benchmarks: one server
process, spoken to as an editor does (Content-Length framing, JSON-RPC
2.0), and every message it sent, kept until it is taken."""

import json
import subprocess
import threading
import time

TIMEOUT = 60


class ServerClient:
    """One server process and what it sent."""

    def __init__(self, mbc, root):
        self.proc = subprocess.Popen([mbc, "lsp"], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE)
        self.root = root
        self.next_id = 1
        self.messages = []
        self.cond = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        out = self.proc.stdout
        while True:
            length = None
            while True:
                line = out.readline()
                if not line:
                    return
                if line in (b"\r\n", b"\n"):
                    break
                name, _, value = line.decode().partition(":")
                if name.lower() == "content-length":
                    length = int(value)
            body = json.loads(out.read(length))
            with self.cond:
                self.messages.append(body)
                self.cond.notify_all()

    def raw(self, data):
        self.proc.stdin.write(data)
        self.proc.stdin.flush()

    def frame(self, message):
        body = json.dumps(message).encode()
        return b"Content-Length: %d\r\n\r\n" % len(body) + body

    def send(self, message):
        self.raw(self.frame(message))

    def request(self, method, params=None, send=True):
        ident = self.next_id
        self.next_id += 1
        message = {"jsonrpc": "2.0", "id": ident, "method": method}
        if params is not None:
            message["params"] = params
        if send:
            self.send(message)
        return ident, message

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def wait(self, test, what):
        deadline = time.time() + TIMEOUT
        with self.cond:
            while True:
                for m in self.messages:
                    if test(m):
                        self.messages.remove(m)
                        return m
                left = deadline - time.time()
                if left <= 0 or self.proc.poll() is not None and not any(
                        test(m) for m in self.messages):
                    if left > 0:
                        self.cond.wait(0.2)
                        if any(test(m) for m in self.messages):
                            continue
                    raise AssertionError(f"no {what} from the server")
                self.cond.wait(left)

    def response(self, ident):
        return self.wait(lambda m: m.get("id") == ident and "method" not in m,
                         f"response to request {ident}")

    def call(self, method, params=None):
        return self.response(self.request(method, params)[0])

    def ask(self, method, uri, line, character):
        """The result of a request at a place of a document."""
        return self.call(method, at(uri, line, character))["result"]

    def diagnostics(self, uri, version=None):
        return self.wait(
            lambda m: m.get("method") == "textDocument/publishDiagnostics"
            and m["params"]["uri"] == uri
            and (version is None or m["params"].get("version") == version),
            f"diagnostics of {uri}")["params"]["diagnostics"]

    def start(self, options=None, encodings=None):
        params = {"processId": None, "rootUri": self.root.as_uri(),
                  "capabilities": {}}
        if encodings:
            params["capabilities"]["general"] = {"positionEncodings": encodings}
        if options is not None:
            params["initializationOptions"] = options
        result = self.call("initialize", params)["result"]
        self.notify("initialized", {})
        return result

    def open(self, name, text, version=1):
        uri = (self.root / name).as_uri()
        self.notify("textDocument/didOpen", {"textDocument": {
            "uri": uri, "languageId": "fanuc-macro-b", "version": version,
            "text": text}})
        return uri

    def stop(self):
        assert self.call("shutdown")["result"] is None
        self.notify("exit", {})
        return self.proc.wait(TIMEOUT)


def at(uri, line, character):
    return {"textDocument": {"uri": uri},
            "position": {"line": line, "character": character}}
