-- book.lua - the pandoc filter that makes a page of the book from a Markdown
-- text of the repository (tools/book/build.sh runs it).
--
-- The text's relative links and images name files of the repository; in the
-- book they lead to the page made from that file (a text of pages.tsv, or a
-- folder whose README.md is one), to the file's listing page (src/PATH.html,
-- for source and other text), or to a copy of it (files/PATH, for images).
-- A code span that is exactly the name of a file beside the text becomes a
-- link to that file's listing.  A code block marked as a snippet
-- (<!-- snippet: PATH#NAME -->, docs/CONTRIBUTING.md) gets a line above it
-- naming its file and lines, linked to the listing.  A table of the page's
-- contents (its headings of levels 2 and 3) follows the first heading, and
-- every heading gets a link to itself.
--
-- The environment says what the filter works on: BOOK_SOURCE, the text (a
-- path from the top of the repository), BOOK_PAGES, the list of pages
-- (pages.sh), and BOOK_NEEDS, a file to which it appends a line for every
-- listing (`listing PATH`) and copy (`copy PATH`) the page needs.  A link
-- that leads nowhere, or into solutions/, stops the build naming the text
-- and line.

local source = assert(os.getenv("BOOK_SOURCE"), "BOOK_SOURCE not set")
local needs_file = assert(os.getenv("BOOK_NEEDS"), "BOOK_NEEDS not set")
local pages = {}
for line in io.lines((assert(os.getenv("BOOK_PAGES"), "BOOK_PAGES not set"))) do
  local src, page = line:match("^([^\t]+)\t([^\t]+)\t")
  if src then pages[src] = page end
end
local source_dir = source:match("^(.*)/") or "."

local function exists(path)
  local f = io.open(path, "r")
  if f then f:close() return true end
  return false
end

local function is_dir(path)
  return exists(path .. "/.") -- opening a folder for reading succeeds on Linux
end

-- The line of the text where `what` first appears, for messages.
local function line_of(what)
  local n = 0
  for line in io.lines(source) do
    n = n + 1
    if line:find(what, 1, true) then return n end
  end
  return 0
end

local function fail(what, message)
  error(string.format("%s:%d: %s", source, line_of(what), message), 0)
end

-- dir/target without "." and "..": a path from the top of the repository,
-- or nil when it leaves the repository.
local function resolve(dir, target)
  local parts = {}
  for part in (dir .. "/" .. target):gmatch("[^/]+") do
    if part == ".." then
      if #parts == 0 then return nil end
      table.remove(parts)
    elseif part ~= "." then
      table.insert(parts, part)
    end
  end
  return table.concat(parts, "/")
end

local needs = assert(io.open(needs_file, "a"))
local function need(kind, path)
  needs:write(kind, " ", path, "\n")
end

local copied = { png = true, jpg = true, jpeg = true, gif = true, svg = true, pdf = true }

-- Where the book has the repository's file `file` (a path from the top).
local function file_target(file, anchor, what)
  if file:match("^solutions/") or file == "solutions" then
    fail(what, file .. " is in solutions/: show the chapters/ file, which students have")
  end
  if is_dir(file) then
    if pages[file .. "/README.md"] then return pages[file .. "/README.md"] .. ".html" .. anchor end
    fail(what, "the link to " .. file .. " is a folder without a page of the book")
  end
  if not exists(file) then fail(what, file .. " does not exist") end
  if pages[file] then return pages[file] .. ".html" .. anchor end
  local ext = (file:match("%.([%w]+)$") or ""):lower()
  if copied[ext] then
    need("copy", file)
    return "files/" .. file .. anchor
  end
  need("listing", file)
  return "src/" .. file .. ".html" .. anchor
end

-- Where the book has what a relative link `target` of the text leads to.
local function book_target(target, what)
  local path, anchor = target:match("^([^#]*)(.*)$")
  if path == "" then return target end
  local file = resolve(source_dir, path)
  if not file or file == "" then fail(what, "the link " .. target .. " leads outside the repository") end
  return file_target(file, anchor, what)
end

local function relative(target)
  return not target:match("^%a[%w+.-]*:") and not target:match("^#")
end

function Image(el)
  if relative(el.src) then el.src = book_target(el.src, el.src) end
  return el
end

-- A link inside a link is not allowed in HTML: the inner one keeps only its text.
local function unlink(inlines)
  return pandoc.Span(inlines):walk({
    Link = function(l) return l.content end,
  }).content
end

function Link(el)
  if relative(el.target) then el.target = book_target(el.target, "](" .. el.target) end
  el.content = unlink(el.content)
  return el
end

function Code(el)
  local file = source_dir .. "/" .. el.text
  if el.text:match("^[%w_-][%w_./-]*$") and not el.text:match("%.%.") and not pages[file] and exists(file)
      and not is_dir(file) then
    return pandoc.Link({ el }, book_target(el.text, "`" .. el.text .. "`"))
  end
end

-- The contents of the page: a list of its level-2 headings, each with its
-- level-3 headings, after the page's first heading.
function Pandoc(doc)
  local toc, last = pandoc.List(), nil
  for _, block in ipairs(doc.blocks) do
    if block.t == "Header" and block.identifier ~= "" and (block.level == 2 or (block.level == 3 and last)) then
      local item = pandoc.Plain({ pandoc.Link(block.content, "#" .. block.identifier) })
      if block.level == 2 then
        last = { item }
        toc:insert(last)
      else
        if #last == 1 then last[2] = pandoc.BulletList({}) end
        last[2].content:insert({ item })
      end
    end
  end
  if #toc == 0 then return doc end
  local at = 1
  for i, block in ipairs(doc.blocks) do
    if block.t == "Header" and block.level == 1 then at = i + 1 break end
  end
  doc.blocks:insert(at, pandoc.RawBlock("html", '<details class="toc" open><summary>Contents</summary><nav>'))
  doc.blocks:insert(at + 1, pandoc.BulletList(toc))
  doc.blocks:insert(at + 2, pandoc.RawBlock("html", "</nav></details>"))
  return doc
end

function Header(el)
  if el.identifier ~= "" then
    el.content:insert(pandoc.Space())
    el.content:insert(pandoc.Link({ pandoc.Str("#") }, "#" .. el.identifier, "", { class = "anchor" }))
  end
  return el
end

-- The first and last line of region `name` of `path` (or of function `name`), as tools/snippets.awk finds it.
local function region_lines(path, name, what)
  if not exists(path) then fail(what, "the snippet's file " .. path .. " does not exist") end
  local n, first, depth = 0, nil, 0
  for line in io.lines(path) do
    n = n + 1
    if not first then
      if line:match("^%s*/%* snippet: " .. name:gsub("%p", "%%%0") .. " %*/%s*$") then
        first, depth = n + 1, 1
      end
    elseif line:match("^%s*/%* snippet: [^ ]+ %*/%s*$") then
      depth = depth + 1
    elseif line:match("^%s*/%* end snippet %*/%s*$") then
      depth = depth - 1
      if depth == 0 then return first, n - 1 end
    end
  end
  -- no region: the definition of function `name` with the comment right above it
  local all = {}
  for line in io.lines(path) do all[#all + 1] = line end
  local pattern = "^[%a_][^(]*[^%w_(]" .. name:gsub("%p", "%%%0") .. "%(" -- the declarator's name, before any (
  for k, line in ipairs(all) do
    if line:match(pattern) and not line:match(";%s*$")
        and not line:match("^typedef") and not line:match("^#") then
      local top = k
      if k > 1 and all[k - 1]:match("%*/%s*$") then
        local j = k - 1
        while j > 1 and all[j]:match("^ %*") do j = j - 1 end
        if all[j]:match("^/%*") then top = j end
      end
      if line:match("}%s*$") then return top, k end
      for e = k + 1, #all do
        if all[e]:match("^}") then return top, e end
      end
    end
  end
  fail(what, "no complete region " .. name .. " and no function " .. name .. " in " .. path .. " (make check-snippets)")
end

function Blocks(blocks)
  local out = pandoc.List()
  local snippet = nil
  for _, block in ipairs(blocks) do
    local marker = block.t == "RawBlock" and block.format == "html" and block.text:match("^<!%-%- snippet: (%S+) %-%->")
    if marker then
      snippet = marker
    elseif block.t == "RawBlock" and block.format == "html" and block.text:match("^<!%-%- end snippet %-%->") then
      snippet = nil
    elseif snippet and block.t == "CodeBlock" then
      local path, name = snippet:match("^([^#]+)#(.+)$")
      local what = "<!-- snippet: " .. snippet
      local first, last = region_lines(path, name, what)
      local href = file_target(path, "#L-" .. first, what)
      local label = string.format("%s, lines %d–%d", path, first, last)
      out:insert(pandoc.Div({
        pandoc.Para({ pandoc.Link({ pandoc.Code(path) }, href), pandoc.Str(string.format(", lines %d–%d", first, last)) }),
        block,
      }, { class = "listing", ["aria-label"] = label }))
      snippet = nil
    else
      out:insert(block)
    end
  end
  return out
end

return {
  { Image = Image, Link = Link, Code = Code },
  { Pandoc = Pandoc },
  { Header = Header, Blocks = Blocks },
}
