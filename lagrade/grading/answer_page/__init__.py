"""The answer page: `lagrade serve` gives each student a private page with their own handout,
one field per part, a live "read as" preview and a save button that writes the answer sheet
`lagrade grade` reads. Modules: `tokens` (private links), `settings` (the assignment's
`[answer_page]` table), `sheets` (reading and saving sheets), `preview` (how an answer is read,
as MathML), `judging` (previews and graded saves in killable workers, one item per student at
a time), `app` (the web application), `deadlines` (read deadlines on every connection)."""
