"""The course-project report: its content as a document (:mod:`.document`), typeset as a PDF
on A4 pages and written as an editable DOCX."""
