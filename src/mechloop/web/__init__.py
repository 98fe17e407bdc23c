"""The local web application (``mechloop serve``): the model editor, the mechanism view,
a plot and the results table in a browser, on the same Python API as the CLI.

Modules: :mod:`.safety` (the folder served, tokens, hosts, request size),
:mod:`.documents` (YAML text → model or located problems), :mod:`.payload` (a solution as
JSON-ready data: the vector diagram of every position and the results table in display
units), :mod:`.worker` (work in a child process with a time limit; :mod:`.preload`, what
its fork server loads once), :mod:`.jobs` (a synthesis in the background, its progress
and cancel), :mod:`.views` (the other plot kinds as SVG), :mod:`.app` (the routes),
:mod:`.serve` (the server started by the CLI), :mod:`.autosave` (the working copy of
the model in the editor), :mod:`.templates` (new models from the bundled ones),
:mod:`.language` (the API's error messages in the page's language), ``static/`` (the page;
no CDN: ``app.js`` the page, ``draw.js`` the diagram and the plot, ``editor.js`` the text
and its undo/redo — ``mechloopEditor.setText`` is how any part changes the model —,
``highlight.js``, ``plotzoom.js``, ``autosave.js``, ``newmodel.js``, ``i18n.js``).

It may import everything of mechloop; nothing of mechloop imports it (only the CLI, and
only inside ``mechloop serve``).  Starlette and uvicorn come with the ``web`` extra.
"""
