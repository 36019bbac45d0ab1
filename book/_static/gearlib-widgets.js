// Loaded on pages with widgets, between require.js and the Jupyter widgets HTML manager
// (book/_config.yml, nb_ipywidgets_js), so that the embedded widgets render from disk.
(function () {
  "use strict";
  var here = document.currentScript && document.currentScript.src;
  if (!here) {
    return;
  }
  // The manager's copy in _static/html-manager (installed from npm by `make vendor`).
  var manager = new URL("html-manager/", here).href;

  // Each AMD module of the manager finds the fonts it bundles next to its own URL, which
  // require.js derives from the module's name, relative to the page. Name those URLs in
  // the local copy, so the fonts load from _static/html-manager on every page.
  var modules = ["base", "base7", "controls", "controls7", "html-manager"];
  var paths = {"@jupyter-widgets/html-manager/dist/libembed-amd": manager + "libembed-amd"};
  modules.forEach(function (name) {
    paths["@jupyter-widgets/" + name] = manager + name;
  });
  window.requirejs.config({paths: paths});
  window.__jupyter_widgets_assets_path__ = manager;

  // The widget controls typeset their labels with MathJax 2's MathJax.Hub.Queue; the book
  // loads MathJax 3. Give MathJax 3 that one entry point (MathJax is deferred, so it is
  // there by DOMContentLoaded, before the widgets render).
  document.addEventListener("DOMContentLoaded", function () {
    var mj = window.MathJax;
    if (!mj || mj.Hub || !mj.startup || typeof mj.typesetPromise !== "function") {
      return;
    }
    mj.Hub = {
      Queue: function () {
        var elements = [];
        Array.prototype.forEach.call(arguments, function (job) {
          if (Array.isArray(job) && job[0] === "Typeset" && job[2]) {
            elements.push(job[2]);
          }
        });
        if (!elements.length) {
          return;
        }
        mj.startup.promise = mj.startup.promise
          .then(function () { return mj.typesetPromise(elements); })
          .catch(function (err) { console.error("MathJax could not typeset a widget label:", err); });
      },
    };
  });
})();
