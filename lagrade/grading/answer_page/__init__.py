"""The answer page: `lagrade serve` gives each student a private page with their own handout,
one field per part, a live "read as" preview and a save button that writes the answer sheet
`lagrade grade` reads. Modules: `tokens` (private links), `settings` (the assignment's
`[answer_page]` table), `due` (the due date: on time, late or refused), `sheets` (reading and
saving sheets, each save logged: `lagrade.grading.savelog`), `saving` (a save under the
student's lock: the due date, the log, one attempt per press), `preview` (how an answer is
read, as MathML, with the parser's notes), `judging` (previews and graded saves in killable
workers, one item per student at a time), `app` (the web application), `deadlines` (read
deadlines on every connection)."""
