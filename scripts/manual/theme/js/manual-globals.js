// The globals the built-in theme's base.js and search read, from the script tag's data
// attribute rather than an inline script (which the service's CSP forbids).
var base_url = document.currentScript.dataset.baseUrl;
var shortcuts = { help: 191, next: 78, previous: 80, search: 83 };
