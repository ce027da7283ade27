// Typesets the equations (LaTeX in <div class="latex">) with the vendored KaTeX; without
// script the LaTeX source stays readable.
document.addEventListener("DOMContentLoaded", function () {
  if (typeof katex === "undefined") return;
  document.querySelectorAll("div.latex").forEach(function (el) {
    katex.render(el.textContent, el, { displayMode: true, throwOnError: false });
  });
});
