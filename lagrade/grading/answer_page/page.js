// The answer page's script (lagrade serve): a live "read as" preview for every field, asked
// of the server at each pause in typing, and the save button. No library, nothing fetched
// from elsewhere: the preview's math is MathML the server wrote from what its parser read.
"use strict";
(function () {
  const base = document.body.dataset.base;
  const fields = Array.from(document.querySelectorAll(".answer"));
  const status = document.getElementById("status");
  const form = document.getElementById("answers");
  const pause = 300; // ms of no typing before a preview is asked
  const timers = new Map();
  const latest = new Map();
  let asked = 0;
  let dirty = false;

  async function post(path, body) {
    const response = await fetch(base + path, {
      method: "POST",
      headers: { "Content-Type": "application/json" },
      body: JSON.stringify(body),
    });
    let data = null;
    try { data = await response.json(); } catch (e) { data = null; }
    if (!response.ok) {
      throw new Error((data && data.message) || "the server answered " + response.status);
    }
    return data;
  }

  function element(tag, cls, text) {
    const el = document.createElement(tag);
    if (cls) el.className = cls;
    if (text !== undefined) el.textContent = text;
    return el;
  }

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
    if (result.message) {
      box.appendChild(element("pre", "error", result.message));
    }
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
      if (latest.get(field) === id) showPreview(box, result);
    } catch (error) {
      if (latest.get(field) === id) {
        box.replaceChildren(element("span", "label", "Preview unavailable: " + error.message));
      }
    } finally {
      if (latest.get(field) === id) box.classList.remove("busy");
    }
  }

  function changed(field) {
    dirty = true;
    status.textContent = "Unsaved changes.";
    status.className = "unsaved";
    clearTimeout(timers.get(field));
    timers.set(field, setTimeout(function () { preview(field); }, pause));
  }

  function showFeedback(feedback, attemptsLeft) {
    fields.forEach(function (field) {
      const box = document.getElementById(field.id + "-feedback");
      box.replaceChildren();
      box.className = "feedback";
      const part = feedback && feedback.parts[field.dataset.problem + "/" + field.dataset.key];
      if (!part) return;
      box.classList.add(part.verdict);
      box.appendChild(element("div", "", part.points + " / " + part.max_points + " points"));
      // a parser's message keeps its columns (the caret); a sentence wraps like prose
      const tag = part.verdict === "invalid" ? "pre" : "p";
      part.feedback.forEach(function (text) { box.appendChild(element(tag, "", text)); });
    });
    const attempts = document.getElementById("attempts");
    if (attempts && attemptsLeft !== null && attemptsLeft !== undefined) {
      attempts.textContent = "Graded saves left: " + attemptsLeft + ".";
    }
  }

  async function save(event) {
    event.preventDefault();
    const answers = {};
    fields.forEach(function (field) {
      const problem = field.dataset.problem;
      answers[problem] = answers[problem] || {};
      answers[problem][field.dataset.key] = field.value;
    });
    status.textContent = "Saving…";
    status.className = "";
    try {
      const reply = await post("/save", { answers: answers });
      dirty = false;
      status.textContent = "Saved at " + reply.saved_at + " (" + reply.file + ").";
      if ("feedback" in reply) {
        if (reply.feedback) showFeedback(reply.feedback, reply.attempts_left);
        else if (reply.message) status.textContent += " Not graded: " + reply.message;
        else status.textContent += " No graded saves left: this one was saved, not graded.";
      }
    } catch (error) {
      status.textContent = "Not saved: " + error.message;
      status.className = "failed";
    }
  }

  fields.forEach(function (field) {
    field.addEventListener("input", function () { changed(field); });
    if (field.value.trim()) preview(field);
  });
  form.addEventListener("submit", save);
  window.addEventListener("beforeunload", function (event) {
    if (dirty) { event.preventDefault(); event.returnValue = ""; }
  });
})();
