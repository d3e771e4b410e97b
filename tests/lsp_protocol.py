#!/usr/bin/env python3
"""`mbc lsp` held to the Language Server Protocol by a client of its own.

Each check starts the server, speaks to it over its standard input and
output as an editor does (Content-Length framing, JSON-RPC 2.0), and checks
what it answers on shop-style programs in a workspace of their own:
lifecycle, diagnostics and their edits, hover, go to definition, document
symbols, positions in UTF-16, cancelled and stale requests, input that
is not what the protocol allows, and the code lenses' runs.

    lsp_protocol.py MBC
"""

import json
import pathlib
import sys
import tempfile

from lsp_client import TIMEOUT, ServerClient, at

MBC = sys.argv[1]
# The workspace's programs (tests/lsp), which tests/lsp_neovim.sh opens too.
FIXTURES = pathlib.Path(__file__).resolve().parent / "lsp"
PART = (FIXTURES / "part.nc").read_text()
LIBRARY = (FIXTURES / "library.nc").read_text()


def Client(root):
    """A server of the mbc under test, its workspace `root`."""
    return ServerClient(MBC, root)


def expect(condition, what):
    if not condition:
        raise AssertionError(what)


def workspace(tmp):
    (tmp / "part.nc").write_text(PART)
    (tmp / "lib").mkdir()
    (tmp / "lib" / "library.nc").write_text(LIBRARY)
    (tmp / "mbc.json").write_text(json.dumps({"include": ["lib"]}))
    return tmp


def with_part(tmp):
    """A started server with part.nc open and analysed."""
    c = Client(tmp)
    c.start()
    uri = c.open("part.nc", PART)
    c.diagnostics(uri)
    return c, uri


def check_lifecycle(tmp):
    c = Client(tmp)
    early = c.call("textDocument/hover", at("file:///x.nc", 0, 0))
    expect(early["error"]["code"] == -32002, f"before initialize: {early}")
    caps = c.start()["capabilities"]
    for capability in ("hoverProvider", "definitionProvider",
                       "documentSymbolProvider"):
        expect(caps.get(capability) is True, f"{capability} in {caps}")
    expect(caps["textDocumentSync"]["change"] == 2, "incremental sync")
    expect(caps["positionEncoding"] == "utf-16", "UTF-16 by default")
    again = c.call("initialize", {"capabilities": {}})
    expect(again["error"]["code"] == -32600, f"initialize twice: {again}")
    expect(c.call("shutdown")["result"] is None, "shutdown")
    late = c.call("textDocument/hover", at("file:///x.nc", 0, 0))
    expect(late["error"]["code"] == -32600, f"after shutdown: {late}")
    c.notify("exit", {})
    expect(c.proc.wait(TIMEOUT) == 0, "exit after shutdown is status 0")
    # Exit without shutdown, and an input that ends: status 1.
    c = Client(tmp)
    c.start()
    c.notify("exit", {})
    expect(c.proc.wait(TIMEOUT) == 1, "exit without shutdown is status 1")
    c = Client(tmp)
    c.start()
    c.proc.stdin.close()
    expect(c.proc.wait(TIMEOUT) == 1, "end of input is status 1")


def check_diagnostics_and_edits(tmp):
    c = Client(tmp)
    c.start()
    text = PART.replace("#1=#1+1", "#1=[#1+")
    uri = c.open("part.nc", text)
    diags = c.diagnostics(uri, 1)
    errors = [d for d in diags if d["severity"] == 1]
    expect(len(errors) == 1 and errors[0]["range"]["start"]["line"] == 11,
           f"one error on line 12: {diags}")
    expect(errors[0]["source"] == "mbc", "source")
    # Called programs come from the workspace's library folder (mbc.json):
    # no missing-program warning.
    expect(not any(d["code"] == "missing-program" for d in diags),
           f"the library's programs are found: {diags}")
    # An incremental edit mends the line; the error goes.
    line = text.splitlines()[11]
    c.notify("textDocument/didChange", {
        "textDocument": {"uri": uri, "version": 2},
        "contentChanges": [{"range": {
            "start": {"line": 11, "character": 0},
            "end": {"line": 11, "character": len(line)}},
            "text": "#1=#1+1"}]})
    diags = c.diagnostics(uri, 2)
    expect(not any(d["severity"] == 1 for d in diags), f"mended: {diags}")
    # A warning with a note: a vacant local reaching an address.
    c.notify("textDocument/didChange", {
        "textDocument": {"uri": uri, "version": 3},
        "contentChanges": [{"text": "%\nO1001(FACE)\nG90G00X#24Y0\nM30\n%\n"}]})
    diags = c.diagnostics(uri, 3)
    vacant = [d for d in diags if d["code"] == "vacant-address"]
    expect(vacant and vacant[0]["severity"] == 2, f"vacant-address: {diags}")
    related = vacant[0].get("relatedInformation", [])
    expect(related and related[0]["location"]["uri"] == uri,
           f"the note as related information: {vacant}")
    c.notify("textDocument/didClose", {"textDocument": {"uri": uri}})
    expect(c.diagnostics(uri) == [], "closing clears the diagnostics")
    expect(c.stop() == 0, "clean exit")


def check_code_actions(tmp):
    c = Client(tmp)
    caps = c.start()["capabilities"]
    expect(caps["codeActionProvider"]["codeActionKinds"] == ["quickfix"],
           f"quick fixes: {caps}")
    text = "%\nO1003(WINDOW)\n#1=5.\nIF[#1=5.]GOTO10\nN10M30\n%\n"
    uri = c.open("window.nc", text)
    diags = c.diagnostics(uri, 1)
    expect(any(d["severity"] == 1 for d in diags), f"'=' in IF: {diags}")
    actions = c.call("textDocument/codeAction", {
        "textDocument": {"uri": uri},
        "range": {"start": {"line": 3, "character": 0},
                  "end": {"line": 3, "character": 0}},
        "context": {"diagnostics": diags}})["result"]
    expect(len(actions) == 1 and actions[0]["title"] == "Replace '=' with 'EQ'"
           and actions[0]["kind"] == "quickfix", f"the fix-it: {actions}")
    edit = actions[0]["edit"]["changes"][uri][0]
    expect(edit["range"]["start"] == {"line": 3, "character": 5}
           and edit["newText"] == "EQ", f"the edit: {edit}")
    # The editor applies it: the error goes.
    c.notify("textDocument/didChange", {
        "textDocument": {"uri": uri, "version": 2},
        "contentChanges": [{"range": edit["range"], "text": edit["newText"]}]})
    expect(not any(d["severity"] == 1 for d in c.diagnostics(uri, 2)),
           "fixed")
    none = c.call("textDocument/codeAction", {
        "textDocument": {"uri": uri},
        "range": {"start": {"line": 1, "character": 0},
                  "end": {"line": 1, "character": 0}},
        "context": {"diagnostics": []}})["result"]
    expect(none == [], f"no fix on a line without one: {none}")
    expect(c.stop() == 0, "clean exit")


def check_hover(tmp):
    c, uri = with_part(tmp)

    def hover(line, character):
        result = c.ask("textDocument/hover", uri, line, character)
        return result["contents"]["value"] if result else ""

    g01 = hover(10, 1)
    expect("**G01**" in g01 and "linear interpolation" in g01
           and "modal group 01" in g01, f"G01: {g01}")
    expect("machine coordinates" in hover(13, 5), "#5021")
    expect("Read only" in hover(13, 5), "#5021 is read only")
    expect("the program's unit (G21 mm, G20 inch)" in hover(13, 5),
           f"#5021's unit: {hover(13, 5)}")
    m98 = hover(14, 1)
    expect("subprogram call" in m98, f"M98: {m98}")
    label = hover(16, 1)
    expect("N100" in label and "1 GOTO" in label, f"N100: {label}")
    lib = c.open("lib/library.nc", LIBRARY)
    c.diagnostics(lib)
    arg = c.call("textDocument/hover", at(lib, 5, 8))["result"]
    expect(arg and "argument `X`" in arg["contents"]["value"],
           f"#24 names its argument: {arg}")
    # A local of a macro read with its callers names the calls that pass
    # it (the library after part.nc in one file: O9040's X#24 on line 23).
    both = c.open("both.nc", PART.replace("M30\n%", "M30\n") + LIBRARY[2:])
    c.diagnostics(both)
    passed = c.ask("textDocument/hover", both, 23, 8)
    expect(passed and "Passed by O1000 line 16" in passed["contents"]["value"],
           f"#24's callers: {passed}")
    # A G code mbc does not execute, and one FANUC does not have.
    c.notify("textDocument/didChange", {
        "textDocument": {"uri": uri, "version": 2},
        "contentChanges": [{"text": "%\nO1(X)\nG12.1\nG04.7\nM30\n%\n"}]})
    c.diagnostics(uri, 2)
    expect("does not execute it yet" in hover(2, 1), "G12.1 unmodelled")
    expect("not a G code" in hover(3, 1), "G04.7 is none")
    expect(c.call("textDocument/hover", at(uri, 0, 0))["result"] is None,
           "nothing to say on %")
    # The #n an assignment writes: a macro alarm's number and the text the
    # control shows (26 characters), a common variable's references.
    c.notify("textDocument/didChange", {
        "textDocument": {"uri": uri, "version": 3},
        "contentChanges": [{"text": "%\nO1(X)\n#100=#5021\n"
                            "IF[#100LT0]THEN#3000=20(Z BELOW TABLE)\n"
                            "#3000=1(TOOL LENGTH OFFSET NOT MEASURED)\n"
                            "#3000=1200(BAD)\nM30\n%\n"}]})
    c.diagnostics(uri, 3)
    expect("alarm **3020** `Z BELOW TABLE`" in hover(3, 16),
           f"#3000=20: {hover(3, 16)}")
    expect("`TOOL LENGTH OFFSET NOT MEA` (the control shows the first 26"
           in hover(4, 1), f"a long message: {hover(4, 1)}")
    expect("raises PS0119" in hover(5, 1), f"#3000=1200: {hover(5, 1)}")
    refs = c.call("textDocument/references", dict(
        at(uri, 2, 2), context={"includeDeclaration": True}))["result"]
    expect(sorted(r["range"]["start"]["line"] for r in refs) == [2, 3],
           f"#100 written on line 2, read on 3: {refs}")
    c.notify("textDocument/didChange", {
        "textDocument": {"uri": uri, "version": 4},
        "contentChanges": [{"text": "%\nO1(X)\n#500=1\nM30\n%\n"}]})
    c.diagnostics(uri, 4)
    expect("mbc run --state keeps it" in hover(2, 1),
           f"#500 and the option that keeps it: {hover(2, 1)}")
    expect(c.stop() == 0, "clean exit")


def check_definition_and_symbols(tmp):
    c, uri = with_part(tmp)

    goto = c.ask("textDocument/definition", uri, 13, 17)
    expect(len(goto) == 1 and goto[0]["uri"] == uri
           and goto[0]["range"]["start"]["line"] == 16, f"GOTO100: {goto}")
    library = (tmp / "lib" / "library.nc").as_uri()
    m98 = c.ask("textDocument/definition", uri, 14, 4)
    expect(len(m98) == 1 and m98[0]["uri"] == library
           and m98[0]["range"]["start"]["line"] == 1, f"M98P2000: {m98}")
    g65 = c.ask("textDocument/definition", uri, 15, 4)
    expect(len(g65) == 1 and g65[0]["range"]["start"]["line"] == 4,
           f"G65P9040: {g65}")
    lib = c.open("lib/library.nc", LIBRARY)
    c.diagnostics(lib)
    back = c.call("textDocument/definition", at(lib, 6, 2))["result"]
    expect(any(d["uri"] == uri and d["range"]["start"]["line"] == 16
               for d in back), f"M99P100 returns to the caller's N100: {back}")
    symbols = c.call("textDocument/documentSymbol",
                     {"textDocument": {"uri": uri}})["result"]
    expect([s["name"] for s in symbols] == ["O1000"], f"programs: {symbols}")
    children = [s["name"] for s in symbols[0]["children"]]
    expect(children == ["DO1", "N100"], f"loop and label: {children}")
    expect(c.stop() == 0, "clean exit")


def check_completion_references_workspace(tmp):
    c, uri = with_part(tmp)
    caps = c.call("workspace/symbol", {"query": ""})  # the index answers
    expect(isinstance(caps["result"], list), f"workspace symbols: {caps}")

    def labels(line, character):
        result = c.ask("textDocument/completion", uri, line, character)
        return {i["label"]: i for i in result["items"]}

    # "#50" in IF[#5021GT0]: the system variables from #5000 on.
    variables = labels(13, 6)
    expect("#5021" in variables and "machine coordinates"
           in variables["#5021"]["detail"], f"#50...: {list(variables)[:5]}")
    edit = variables["#5021"]["textEdit"]["range"]
    expect(edit["start"] == {"line": 13, "character": 3}, f"replaces #50: {edit}")
    # "G0" of G01: the G codes starting so, as programs write them.
    codes = labels(10, 2)
    expect("G01" in codes and "G04" in codes and "G17" not in codes,
           f"G0...: {list(codes)}")
    # After GOTO: the program's labels.
    expect(list(labels(13, 19)) == ["100"], "GOTO's labels")
    # A function where an expression is begun, inside brackets.
    half = c.open("half.nc", "%\nO1004\n#2=[CO\n%\n")
    c.diagnostics(half)
    names = [i["label"] for i in
             c.ask("textDocument/completion", half, 2, 6)["items"]]
    expect(names == ["COS"], f"CO...: {names}")
    # References: #5021 (a system variable) everywhere it is read; N100
    # with its GOTO; a program with its calls across open documents.
    refs = c.call("textDocument/references", dict(
        at(uri, 16, 1), context={"includeDeclaration": True}))["result"]
    lines = sorted(r["range"]["start"]["line"] for r in refs)
    expect(lines == [13, 16], f"N100 and its GOTO: {refs}")
    lib = c.open("lib/library.nc", LIBRARY)
    c.diagnostics(lib)
    calls = c.call("textDocument/references", dict(
        at(lib, 4, 1), context={"includeDeclaration": False}))["result"]
    expect([(r["uri"], r["range"]["start"]["line"]) for r in calls]
           == [(uri, 15)], f"O9040's call in part.nc: {calls}")
    # Workspace symbols: the library's programs, by any part of the name.
    found = c.call("workspace/symbol", {"query": "904"})["result"]
    expect([s["name"] for s in found] == ["O9040"]
           and found[0]["location"]["uri"].endswith("lib/library.nc")
           and found[0]["location"]["range"]["start"]["line"] == 4,
           f"O9040 in the workspace: {found}")
    expect(c.stop() == 0, "clean exit")


def check_argument_letters(tmp):
    c, uri = with_part(tmp)
    lib = c.open("lib/library.nc", LIBRARY)
    c.diagnostics(lib)
    # G90G01X#24Y#25 in O9040: X and Y after the variables.
    hints = c.call("textDocument/inlayHint", {
        "textDocument": {"uri": lib},
        "range": {"start": {"line": 0, "character": 0},
                  "end": {"line": 8, "character": 0}}})["result"]
    expect([(h["label"], h["position"]) for h in hints]
           == [("X", {"line": 5, "character": 10}),
               ("Y", {"line": 5, "character": 14})], f"hints: {hints}")
    # None in the main program, whose locals no call sets.
    main = c.call("textDocument/inlayHint", {
        "textDocument": {"uri": uri},
        "range": {"start": {"line": 0, "character": 0},
                  "end": {"line": 20, "character": 0}}})["result"]
    expect(main == [], f"no hints in O1000: {main}")
    # In G65P9040X10.Y5.: the letters O9040 reads, Y the one being written.
    help = c.ask("textDocument/signatureHelp", uri, 15, 12)
    sig = help["signatures"][0]
    expect(sig["label"] == "O9040 X Y"
           and [p["label"] for p in sig["parameters"]] == ["X", "Y"]
           and sig["activeParameter"] == 1, f"signature: {help}")
    expect(c.ask("textDocument/signatureHelp", uri, 14, 3) is None,
           "an M98 passes no arguments")
    expect(c.stop() == 0, "clean exit")


def check_semantic_tokens(tmp):
    c = Client(tmp)
    legend = c.start()["capabilities"]["semanticTokensProvider"]["legend"]
    text = ("%\nO1000(PLATE)\nG90G01X#24Y[#5021+1.]F300.\n"
            "IF[#1EQ0]GOTO10\nN10DPRNT[X#24[53]*Y#[#1+2][53]]\nM30\n%\n")
    uri = c.open("colours.nc", text)
    c.diagnostics(uri)
    data = c.call("textDocument/semanticTokens/full",
                  {"textDocument": {"uri": uri}})["result"]["data"]
    lines = text.split("\n")
    tokens = []
    line = column = 0
    for i in range(0, len(data), 5):
        d_line, d_column, length, kind, modifiers = data[i:i + 5]
        line += d_line
        column = d_column if d_line else column + d_column
        names = [m for b, m in enumerate(legend["tokenModifiers"])
                 if modifiers >> b & 1]
        tokens.append((lines[line][column:column + length],
                       legend["tokenTypes"][kind], names))
    expect(tokens[:4] == [("O1000", "namespace", []),
                          ("(PLATE)", "comment", []),
                          ("G90", "keyword", []), ("G01", "keyword", [])],
           f"the header and G codes: {tokens[:4]}")
    expect(("#5021", "variable", ["readonly", "defaultLibrary"]) in tokens,
           f"a read-only system variable: {tokens}")
    expect(("#24", "variable", []) in tokens and ("X", "property", []) in tokens
           and ("GOTO", "keyword", []) in tokens
           and ("N10", "enumMember", []) in tokens, f"the rest: {tokens}")
    # DPRNT's text is text, its variables variables, after them as before.
    printed = tokens[tokens.index(("DPRNT", "keyword", [])) + 1:]
    expect(printed == [("X", "string", []), ("#24", "variable", []),
                       ("53", "number", []), ("*Y", "string", []),
                       ("#", "variable", []), ("#1", "variable", []),
                       ("+", "operator", []), ("2", "number", []),
                       ("53", "number", []), ("M30", "keyword", [])],
           f"DPRNT: {printed}")
    expect(c.stop() == 0, "clean exit")


def check_workspace_changes(tmp):
    c = Client(tmp)
    c.start()
    text = "%\nO1005(PLATE)\nG65P9050X1.\nM30\n%\n"
    uri = c.open("plate.nc", text)
    expect([d["code"] for d in c.diagnostics(uri, 1)] == ["missing-program"],
           "O9050 is nowhere yet")
    # A library written after the server started: the editor's watcher
    # says so, and the document is read again with it.
    (tmp / "lib" / "later.nc").write_text("%\nO9050(LATER)\nG01X#24\nM99\n%\n")
    c.notify("workspace/didChangeWatchedFiles", {"changes": [
        {"uri": (tmp / "lib" / "later.nc").as_uri(), "type": 1}]})
    expect(c.diagnostics(uri, 1) == [], "O9050 found in the new library")
    # Removed again, then saved: the warning is back.
    (tmp / "lib" / "later.nc").unlink()
    c.notify("textDocument/didSave", {"textDocument": {
        "uri": (tmp / "lib" / "later.nc").as_uri()}})
    expect([d["code"] for d in c.diagnostics(uri, 1)] == ["missing-program"],
           "gone with the file")
    expect(c.stop() == 0, "clean exit")


def check_positions(tmp):
    # A character beyond the BMP counts two UTF-16 units, one character in
    # UTF-8 its four bytes.
    text = "%\nO1002\n(\U0001F600 FACE)G90G01X1.F100.\nM30\n%\n"
    for encodings, column in ((None, 12), (["utf-8"], 14)):
        c = Client(tmp)
        caps = c.start(encodings=encodings)["capabilities"]
        uri = c.open("emoji.nc", text)
        c.diagnostics(uri)
        hover = c.call("textDocument/hover", at(uri, 2, column + 1))["result"]
        expect(hover and "G01" in hover["contents"]["value"],
               f"{caps['positionEncoding']}: G01 at {column + 1}: {hover}")
        start = hover["range"]["start"]["character"]
        expect(start == column, f"{caps['positionEncoding']}: {start}")
        expect(c.stop() == 0, "clean exit")


def check_cancel_and_stale(tmp):
    c = Client(tmp)
    c.start()
    # A long document keeps the server busy while the next messages arrive
    # together.
    big = "%\nO5000(3D FINISH)\n" + "".join(
        f"G01X{i % 97}.Y{i % 89}.Z-{i % 7}.F1500.\n" for i in range(60000)) \
        + "M30\n%\n"
    slow = c.open("big.nc", big)
    uri = c.open("part.nc", PART)
    ident, hover = c.request("textDocument/hover", at(uri, 10, 1), send=False)
    cancel = c.frame({"jsonrpc": "2.0", "method": "$/cancelRequest",
                      "params": {"id": ident}})
    c.raw(c.frame(hover) + cancel)
    expect(c.response(ident)["error"]["code"] == -32800, "cancelled")
    ident, hover = c.request("textDocument/hover", at(slow, 1, 1), send=False)
    change = c.frame({"jsonrpc": "2.0", "method": "textDocument/didChange",
                      "params": {"textDocument": {"uri": slow, "version": 2},
                                 "contentChanges": [{"text": "%\nO1(X)\n%\n"}]}})
    c.raw(c.frame(hover) + change)
    expect(c.response(ident)["error"]["code"] == -32801, "stale")
    expect(c.stop() == 0, "clean exit")


def check_bad_input(tmp):
    c = Client(tmp)
    c.start()
    c.raw(b"Content-Length: 9\r\n\r\n{not json")
    expect(c.wait(lambda m: m.get("error", {}).get("code") == -32700,
                  "parse error")["id"] is None, "a parse error has no id")
    unknown = c.call("workspace/dance", {})
    expect(unknown["error"]["code"] == -32601, f"unknown method: {unknown}")
    bad = c.call("textDocument/hover", {"textDocument": {"uri": 5}})
    expect(bad["error"]["code"] == -32602, f"bad params: {bad}")
    c.send({"jsonrpc": "2.0", "id": 99, "method": 7})
    expect(c.response(99)["error"]["code"] == -32600, "method not a string")
    # Members of the wrong type: read as absent where the protocol allows
    # (a version, includeDeclaration), else InvalidParams; the server goes on.
    odd = c.open("odd.nc", "%\nO1(X)\nM30\n%\n", version="seven")
    expect(c.diagnostics(odd, 0) == [], "a version that is no number is 0")
    wrong = c.call("textDocument/references", {
        "textDocument": {"uri": odd}, "position": {"line": 1, "character": 0},
        "context": {"includeDeclaration": "yes"}})
    expect(wrong.get("result") == [], f"a wrong includeDeclaration: {wrong}")
    fresh = Client(tmp)
    bad = fresh.call("initialize", {"capabilities": 5})
    expect(bad["error"]["code"] == -32602, f"capabilities not an object: {bad}")
    expect("capabilities" in fresh.start(), "then initialize again, right")
    expect(fresh.stop() == 0, "clean exit")
    # Framing errors are logged and reading goes on.
    c.raw(b"Content-Type: x\r\n\r\n")
    c.raw(b"Content-Length: banana\r\n\r\n")
    c.raw(b"no colon here\r\n\r\n")
    logs = [c.wait(lambda m: m.get("method") == "window/logMessage",
                   "a log of the bad header")["params"]["message"]
            for _ in range(3)]
    expect(all("mbc lsp" in log for log in logs), f"logged: {logs}")
    # A document that is no Macro B, and one of 100 000 lines.
    uri = c.open("notes.py", "import os\nprint('\\x00 \u00e9')\n" * 50)
    expect(isinstance(c.diagnostics(uri), list), "a Python file")
    big = "%\nO6000\n" + "G01X1.Y2.F100.\n" * 100000 + "M30\n%\n"
    uri = c.open("huge.nc", big)
    c.diagnostics(uri)
    symbols = c.call("textDocument/documentSymbol",
                     {"textDocument": {"uri": uri}})["result"]
    expect(symbols[0]["name"] == "O6000", "the huge program's symbol")
    expect(c.stop() == 0, "the server survived it all")


CHECKS = """%
O3000(DRILL CHECK)
G90G54G0X0Y0Z50.
#3000=11(PROBE NOT TRIPPED)
M30
O3001(CORNER CHECK)
G65P9040X10.Y5.
M99
O3002(ENDLESS)
WHILE[1EQ1]DO1
#1=#1+1
END1
M99
%
"""


def check_code_lenses(tmp):
    c = Client(tmp)
    c.start()
    uri = c.open("part.nc", PART)
    lenses = c.call("textDocument/codeLens",
                    {"textDocument": {"uri": uri}})["result"]
    expect([lens["range"]["start"]["line"] for lens in lenses] == [1],
           f"one lens, on O1000's line: {lenses}")
    first = lenses[0]

    def title(lens):
        command = c.call("codeLens/resolve", lens)["result"]["command"]
        expect(command["command"] == "mbc.showRun" and
               command["arguments"] == [lens["data"]["uri"],
                                        lens["data"]["program"]],
               f"the lens's command: {command}")
        return command["title"]

    # By hand: G91 from line 6 on, so X moves 0, 10 and 20 (30 mm at F300,
    # 6 s), Z25 and Z50 rapids (75 mm at the built-in 10000 mm/min, 0.45 s),
    # X0Y0 a rapid of none; #5021 is 25, so the calls are jumped over.
    got = title(first)
    expect(got == "6 moves \u00b7 0:06.5 \u00b7 ends", f"O1000's lens: {got}")
    # The run is of the text as edited, not as saved: a fourth pass adds
    # 30 mm, 6 s.
    c.notify("textDocument/didChange", {
        "textDocument": {"uri": uri, "version": 2},
        "contentChanges": [{"range": {"start": {"line": 9, "character": 10},
                                      "end": {"line": 9, "character": 11}},
                            "text": "4"}]})
    lenses = c.call("textDocument/codeLens",
                    {"textDocument": {"uri": uri}})["result"]
    got = title(lenses[0])
    expect(got == "7 moves \u00b7 0:12.5 \u00b7 ends", f"after the edit: {got}")
    stale = c.call("codeLens/resolve", first)
    expect(stale.get("error", {}).get("code") == -32801,
           f"a lens of the old text is stale: {stale}")

    # The alarm and where it is, in the document or in the library; a loop
    # that never ends stops at the budget.
    uri = c.open("checks.nc", CHECKS)
    lenses = c.call("textDocument/codeLens",
                    {"textDocument": {"uri": uri}})["result"]
    titles = [title(lens) for lens in lenses]
    expect(len(titles) == 3, f"a lens per program: {titles}")
    expect(titles[0].startswith("1 move \u00b7") and titles[0].endswith(
        "alarm 3011 PROBE NOT TRIPPED (line 4)"), f"O3000's lens: {titles[0]}")
    expect("alarm PS0011 FEED ZERO" in titles[1] and
           titles[1].endswith("(library.nc:6)"), f"O3001's lens: {titles[1]}")
    expect(titles[2].startswith("0 moves") and
           "stopped after 5000000 blocks" in titles[2],
           f"O3002's lens: {titles[2]}")
    # 2 500 000 moves to the budget: a lens keeps none of them (their JSONL
    # took the server's peak 450 MB higher). The peak's growth is measured:
    # a sanitized server starts higher.
    def peak():
        return next(int(line.split()[1]) for line in
                    open(f"/proc/{c.proc.pid}/status")
                    if line.startswith("VmHWM:"))
    uri = c.open("passes.nc", "%\nO3003(ENDLESS PASSES)\nWHILE[1EQ1]DO1\n"
                 "G01X1.F100.\nG01X0\nEND1\nM99\n%\n")
    lenses = c.call("textDocument/codeLens",
                    {"textDocument": {"uri": uri}})["result"]
    before = peak()
    got = title(lenses[0])
    expect(got.startswith("2500000 moves"), f"O3003's lens: {got}")
    expect(peak() - before < 200 * 1024,
           f"the server's peak memory grew {peak() - before} kB in the run")
    c.stop()

    # The command writes the run's view and has the editor open it, or
    # says where it is to an editor that cannot.
    for opens in (True, False):
        c = Client(tmp)
        caps = {"window": {"showDocument": {"support": opens}}}
        c.call("initialize", {"processId": None, "rootUri": tmp.as_uri(),
                              "capabilities": caps})
        c.notify("initialized", {})
        uri = c.open("part.nc", PART)
        result = c.call("workspace/executeCommand", {
            "command": "mbc.showRun", "arguments": [uri, "O1000"]})["result"]
        page = pathlib.Path(result["uri"].removeprefix("file://"))
        expect("three" in page.read_text() and '"line":[7,8,11,11,11,17]' in
               page.read_text(), f"the view holds the run: {page}")
        if opens:
            shown = c.wait(lambda m: m.get("method") == "window/showDocument",
                           "window/showDocument")
            expect(shown["params"] == {"uri": result["uri"], "external": True},
                   f"the browser is asked for: {shown}")
            c.send({"jsonrpc": "2.0", "id": shown["id"],
                    "result": {"success": True}})
        else:
            said = c.wait(lambda m: m.get("method") == "window/showMessage",
                          "window/showMessage")
            expect(str(page) in said["params"]["message"],
                   f"the view's path is said: {said}")
        expect(c.stop() == 0, "the server ended well")
        expect(not page.exists(), "the session's views go with it")


def main():
    checks = [check_lifecycle, check_diagnostics_and_edits, check_code_actions,
              check_hover, check_completion_references_workspace,
              check_argument_letters, check_semantic_tokens,
              check_workspace_changes,
              check_definition_and_symbols, check_positions,
              check_cancel_and_stale, check_bad_input, check_code_lenses]
    failures = 0
    for check in checks:
        with tempfile.TemporaryDirectory() as tmp:
            try:
                check(workspace(pathlib.Path(tmp)))
                print(f"ok   {check.__name__}")
            except AssertionError as e:
                failures += 1
                print(f"FAIL {check.__name__}: {e}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
