-- Driven by tests/lsp_neovim.sh: Neovim's own LSP client against `mbc lsp`
-- on the program the editor opened. Each check writes a line to the report
-- the script names; the script compares it with what it expects.
local report = assert(io.open(vim.env.MBC_NVIM_REPORT, "w"))
local function say(line)
  report:write(line .. "\n")
  report:flush()
end

local buf = vim.api.nvim_get_current_buf()
-- The client attaches, and the diagnostics of the document arrive.
local attached = vim.wait(20000, function()
  return #vim.lsp.buf_get_clients(buf) > 0 and #vim.diagnostic.get(buf) > 0
end, 50)
say("attached " .. tostring(attached))
for _, d in ipairs(vim.diagnostic.get(buf)) do
  say(string.format("diagnostic %d %s", d.lnum + 1, d.code or ""))
end

local function request(method, line, col)
  vim.api.nvim_win_set_cursor(0, {line, col})
  local params = vim.lsp.util.make_position_params()
  local results = vim.lsp.buf_request_sync(buf, method, params, 20000) or {}
  for _, r in pairs(results) do
    if r.result then
      return r.result
    end
  end
  return nil
end

local hover = request("textDocument/hover", 11, 1)
say("hover " .. (hover and hover.contents.value:gsub("\n.*", "") or "none"))
local target = request("textDocument/definition", 14, 18)
if target and target[1] then
  say(string.format("definition %s %d", vim.fn.fnamemodify(
      vim.uri_to_fname(target[1].uri), ":t"), target[1].range.start.line + 1))
else
  say("definition none")
end
-- The lens of O1000, resolved: its run.
vim.lsp.codelens.refresh()
local lens
vim.wait(20000, function()
  for _, l in ipairs(vim.lsp.codelens.get(buf)) do
    if l.command then
      lens = l
    end
  end
  return lens ~= nil
end, 50)
if lens then
  say(string.format("lens %d %s", lens.range.start.line + 1, lens.command.title))
else
  say("lens none")
end
report:close()
vim.cmd("qall!")
