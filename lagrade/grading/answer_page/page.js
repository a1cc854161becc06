// The answer page's script (lagrade serve): a live "read as" preview for every field, asked
// of the server at each pause in typing, and the save button. No library, nothing fetched
// from elsewhere: the preview's math is MathML the server wrote from what its parser read.
//
// What it promises the student:
// - nothing typed is lost: each field counts its edits, and a save marks saved only the
//   edits it sent (what is typed while a save is in flight stays unsaved, and says so); every
//   edit is kept in this browser (localStorage) until a save holds it, and restored, with a
//   notice, when the page is opened again;
// - one press, at most one attempt: the button does nothing while a save is in flight, each
//   press carries an attempt token (the same one when a press whose reply never came is
//   retried), and in graded mode Enter in a field does not save;
// - a lost connection says what to do; the fixed save bar never hides the focused field.
"use strict";
(function () {
  const base = document.body.dataset.base;
  const graded = document.body.dataset.feedback === "on";
  const fields = Array.from(document.querySelectorAll(".answer"));
  const status = document.getElementById("status");
  const form = document.getElementById("answers");
  const button = document.getElementById("save");
  const savebar = document.getElementById("savebar");
  const draftNotice = document.getElementById("draft-notice");
  const pause = 300; // ms of no typing before a preview is asked
  const timers = new Map();
  const latest = new Map(); // field → the id of its newest preview
  const typed = new Map(); // field → how many edits it has had
  const held = new Map(); // field → how many of them the server holds
  const draftKey = "lagrade-draft:" + base;
  let asked = 0;
  let inFlight = false;
  let pending = null; // {token, sent}: a press whose reply never came, retried with its token
  const NO_SERVER =
    "The server could not be reached, so nothing was saved. Your answers are kept in this " +
    "browser: check your connection (or ask your instructor whether the answer page is " +
    "running), then press Save again. If you close this page, they come back when you open " +
    "your link again.";

  // --- talking to the server ---------------------------------------------------------------
  async function post(path, body) {
    let response;
    try {
      response = await fetch(base + path, {
        method: "POST",
        headers: { "Content-Type": "application/json" },
        body: JSON.stringify(body),
      });
    } catch (e) {
      const error = new Error("the server could not be reached");
      error.network = true;
      throw error;
    }
    let data = null;
    try { data = await response.json(); } catch (e) { data = null; }
    if (!response.ok) {
      const error = new Error((data && data.message) || "the server answered " + response.status);
      error.status = response.status;
      throw error;
    }
    return data;
  }

  function element(tag, cls, text) {
    const el = document.createElement(tag);
    if (cls) el.className = cls;
    if (text !== undefined) el.textContent = text;
    return el;
  }

  // --- keeping things in reach -------------------------------------------------------------
  // A box that scrolls sideways (a long formula, a parser's message with its caret, a wide
  // table) gets a tab stop and a name, so a keyboard can scroll it; one that fits gets none.
  function reachable(box, name) {
    if (box.scrollWidth > box.clientWidth + 1) {
      box.tabIndex = 0;
      box.setAttribute("role", "region");
      box.setAttribute("aria-label", name + " (scrolls sideways)");
    } else {
      box.removeAttribute("tabindex");
      box.removeAttribute("role");
      box.removeAttribute("aria-label");
    }
  }

  // "problem 1, eom, 2": whose preview or feedback a box is in, and which of its boxes
  function partName(box) {
    const owner = box.closest(".preview, .feedback");
    if (!owner) return "";
    const field = document.getElementById(owner.id.replace(/-(preview|feedback)$/, ""));
    const boxes = Array.from(owner.querySelectorAll(box.tagName));
    const which = boxes.length > 1 ? ", " + (boxes.indexOf(box) + 1) : "";
    return field ? "problem " + field.dataset.problem + ", " + field.dataset.key + which : "";
  }

  function reachAll(root) {
    root.querySelectorAll(".scroller").forEach(function (box) {
      reachable(box, box.dataset.label || "Table");
    });
    root.querySelectorAll(".preview .math").forEach(function (box) {
      reachable(box, "Read as, " + partName(box));
    });
    root.querySelectorAll(".preview pre").forEach(function (box) {
      reachable(box, "Reading error, " + partName(box));
    });
    root.querySelectorAll(".feedback pre").forEach(function (box) {
      reachable(box, "Feedback, " + partName(box));
    });
  }

  // The save bar is fixed at the bottom: the page keeps room for it, and the focused element
  // (and the preview under a field being typed in) is scrolled above it (WCAG 2.2 2.4.11).
  function fitSavebar() {
    const height = savebar.offsetHeight;
    document.documentElement.style.scrollPaddingBottom = height + 16 + "px";
    document.body.style.paddingBottom = height + 32 + "px";
  }

  function keepAboveSavebar(el) {
    if (!el || savebar.contains(el)) return;
    const rect = el.getBoundingClientRect();
    const limit = savebar.getBoundingClientRect().top - 8;
    if (rect.bottom > limit) {
      window.scrollBy(0, Math.min(rect.bottom - limit, Math.max(rect.top - 8, 0)));
    }
  }

  // --- the preview -------------------------------------------------------------------------
  function showPreview(box, result) {
    box.replaceChildren();
    if (result.status === "read" && result.lines.length) {
      result.lines.forEach(function (line, k) {
        const row = element("div", "line");
        row.appendChild(element("span", "label", k === 0 ? "Read as" : ""));
        const math = element("span", "math");
        if (line.mathml) {
          math.innerHTML = line.mathml; // MathML the server printed from a parsed formula
        } else {
          math.appendChild(element("code", "", line.plain));
        }
        row.appendChild(math);
        box.appendChild(row);
      });
    }
    (result.warnings || []).forEach(function (text) {
      box.appendChild(element("p", "note", "Note: " + text));
    });
    if (result.message) {
      box.appendChild(element("pre", "error", result.message));
    }
    reachAll(box);
  }

  async function preview(field) {
    const id = ++asked;
    latest.set(field, id);
    const box = document.getElementById(field.id + "-preview");
    box.classList.add("busy");
    try {
      const result = await post("/preview", {
        problem: Number(field.dataset.problem), key: field.dataset.key, text: field.value,
      });
      if (latest.get(field) === id && result.status !== "superseded") showPreview(box, result);
    } catch (error) {
      if (latest.get(field) === id) {
        const why = error.network ? "the server could not be reached" : error.message;
        box.replaceChildren(element("span", "label", "Preview unavailable: " + why + "."));
      }
    } finally {
      if (latest.get(field) === id) {
        box.classList.remove("busy");
        if (document.activeElement === field) keepAboveSavebar(box);
      }
    }
  }

  // --- what is typed, what is saved --------------------------------------------------------
  function answers() {
    const out = {};
    fields.forEach(function (field) {
      const problem = field.dataset.problem;
      out[problem] = out[problem] || {};
      out[problem][field.dataset.key] = field.value;
    });
    return out;
  }

  function unsaved() {
    return fields.some(function (field) { return typed.get(field) !== held.get(field); });
  }

  function setStatus(text, cls) {
    status.textContent = text;
    status.className = cls || "";
  }

  function keepDraft() {
    try {
      localStorage.setItem(draftKey, JSON.stringify({
        base: loaded, at: new Date().toISOString(), answers: answers(),
      }));
    } catch (e) { /* storage off or full: the page still works, without the safety net */ }
  }

  function dropDraft() {
    try { localStorage.removeItem(draftKey); } catch (e) { /* nothing kept */ }
  }

  function changed(field) {
    typed.set(field, typed.get(field) + 1);
    keepDraft();
    setStatus("Unsaved changes.", "unsaved");
    clearTimeout(timers.get(field));
    timers.set(field, setTimeout(function () { preview(field); }, pause));
  }

  // --- saving ------------------------------------------------------------------------------
  function showFeedback(feedback, attemptsLeft) {
    fields.forEach(function (field) {
      const box = document.getElementById(field.id + "-feedback");
      box.replaceChildren();
      box.className = "feedback";
      const part = feedback && feedback.parts[field.dataset.problem + "/" + field.dataset.key];
      if (!part) return;
      box.classList.add(part.verdict);
      box.appendChild(element("div", "", part.points + " / " + part.max_points + " points"));
      // a sentence wraps like prose; a parser's message keeps its columns (the answer line
      // and the caret under it): the first line a sentence, the rest kept as written
      part.feedback.forEach(function (text) {
        const at = text.indexOf("\n");
        box.appendChild(element("p", "", at < 0 ? text : text.slice(0, at)));
        const source = at < 0 ? "" : text.slice(at + 1);
        if (source.trim()) box.appendChild(element("pre", "", source));
      });
      reachAll(box);
    });
    const attempts = document.getElementById("attempts");
    if (attempts && attemptsLeft !== null && attemptsLeft !== undefined) {
      attempts.textContent = "Graded saves left: " + attemptsLeft + ".";
    }
  }

  function newToken() {
    const bytes = new Uint8Array(16);
    crypto.getRandomValues(bytes); // (randomUUID needs https; a course may serve plain http)
    return Array.from(bytes, function (b) { return b.toString(16).padStart(2, "0"); }).join("");
  }

  function busy(on) {
    inFlight = on;
    // aria-disabled, not disabled: a disabled button would drop the keyboard's focus
    button.setAttribute("aria-disabled", on ? "true" : "false");
  }

  async function save(event) {
    event.preventDefault();
    if (inFlight || button.disabled) return; // a second click or Enter while one is in flight
    const sent = new Map(fields.map(function (field) { return [field, typed.get(field)]; }));
    const body = answers();
    const text = JSON.stringify(body);
    const token = pending && pending.text === text ? pending.token : newToken();
    pending = { token: token, text: text };
    busy(true);
    setStatus("Saving…");
    try {
      const reply = await post("/save", { answers: body, attempt: token });
      pending = null;
      fields.forEach(function (field) {
        if (typed.get(field) === sent.get(field)) held.set(field, sent.get(field));
      });
      let said = "Saved at " + reply.saved_at + " (" + reply.file + ").";
      if (reply.note) said += " " + reply.note;
      if ("feedback" in reply) {
        if (reply.feedback) showFeedback(reply.feedback, reply.attempts_left);
        else said += " No graded saves left: this one was saved, not graded.";
        if (reply.repeated) said += " " + reply.repeated;
      }
      if (unsaved()) {
        setStatus(said + " You typed more while it was saving: press Save again to keep that.",
          "unsaved");
      } else {
        setStatus(said, reply.late ? "late" : "");
        dropDraft();
      }
    } catch (error) {
      if (error.network) {
        setStatus(NO_SERVER, "failed");
      } else {
        pending = null;
        setStatus("Not saved: " + error.message, "failed");
        if (error.status === 403) button.disabled = true; // the due date has passed
      }
    } finally {
      busy(false);
    }
  }

  // --- answers kept in this browser --------------------------------------------------------
  const loaded = JSON.stringify(answers()); // what the server's sheet filled in

  function fill(values, edited) {
    fields.forEach(function (field) {
      const table = values[field.dataset.problem] || {};
      const value = table[field.dataset.key];
      if (typeof value === "string" && value !== field.value) {
        field.value = value;
        typed.set(field, edited ? typed.get(field) + 1 : held.get(field));
        preview(field);
      }
    });
  }

  function restore(draft) {
    fill(draft.answers, true);
    setStatus("Unsaved changes.", "unsaved");
  }

  function offerDraft() {
    let draft = null;
    try { draft = JSON.parse(localStorage.getItem(draftKey) || "null"); } catch (e) { draft = null; }
    if (!draft || typeof draft.answers !== "object" || JSON.stringify(draft.answers) === loaded) {
      dropDraft();
      return;
    }
    const when = new Date(draft.at).toLocaleString();
    const discard = element("button", "", "Discard them");
    discard.type = "button";
    discard.addEventListener("click", function () {
      dropDraft();
      if (draft.base === loaded) fill(JSON.parse(loaded), false); // back to the saved sheet
      if (!unsaved()) setStatus("Your saved answers are filled in.");
      draftNotice.hidden = true;
    });
    if (draft.base === loaded) {
      restore(draft);
      draftNotice.replaceChildren(
        element("p", "", "Restored the answers you typed in this browser (" + when + "), " +
          "which were not saved. Press Save to keep them."), discard);
    } else {
      const bring = element("button", "", "Restore them");
      bring.type = "button";
      bring.addEventListener("click", function () {
        restore(draft);
        draftNotice.hidden = true;
      });
      draftNotice.replaceChildren(
        element("p", "", "This browser kept answers you typed (" + when + ") that were not " +
          "saved, but your saved answers have changed since. Restore them?"), bring, discard);
    }
    draftNotice.hidden = false;
  }

  // --- start -------------------------------------------------------------------------------
  fields.forEach(function (field) {
    typed.set(field, 0);
    held.set(field, 0);
  });
  fields.forEach(function (field) {
    if (field.value.trim()) preview(field);
  });
  offerDraft();
  fields.forEach(function (field) {
    field.addEventListener("input", function () { changed(field); });
    if (graded && field.tagName === "INPUT") {
      field.addEventListener("keydown", function (event) {
        if (event.key === "Enter") event.preventDefault(); // only the button spends an attempt
      });
    }
  });
  form.addEventListener("submit", save);
  document.addEventListener("focusin", function (event) { keepAboveSavebar(event.target); });
  fitSavebar();
  reachAll(document);
  window.addEventListener("resize", function () { fitSavebar(); reachAll(document); });
  if (window.ResizeObserver) new ResizeObserver(fitSavebar).observe(savebar);
  window.addEventListener("beforeunload", function (event) {
    if (unsaved()) { event.preventDefault(); event.returnValue = ""; }
  });
})();
