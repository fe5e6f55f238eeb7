// Keeping the page's work: each example's edits in the browser's storage (they survive a
// reload), a share link (the edited files, compressed, in the URL's fragment), and downloads.
//
// Edits are {scenarios: {fileName: text}, sketch: text}: only files that differ from the
// example's own are kept (sketch absent when it is the example's).
"use strict";

const KEEP_PREFIX = "stepdance.edits.";
/// The share link's fragment: `#<Example>&edits=<base64url of deflate-raw(JSON)>`.
const SHARE_KEY = "edits";

const keep = (window.stepdanceKeep = {
  /// The edits kept for example `name`, or null. Context: the page.
  load(name) {
    try {
      const text = localStorage.getItem(KEEP_PREFIX + name);
      return text ? JSON.parse(text) : null;
    } catch (error) {
      return null; // no storage (a private window), or a damaged entry: nothing kept
    }
  },

  /// Keeps `edits` for example `name` (none: forgets them); false when the browser refused.
  store(name, edits) {
    try {
      if (keep.empty(edits)) localStorage.removeItem(KEEP_PREFIX + name);
      else localStorage.setItem(KEEP_PREFIX + name, JSON.stringify(edits));
      return true;
    } catch (error) {
      return false;
    }
  },

  empty(edits) {
    return !edits || (Object.keys(edits.scenarios || {}).length === 0 && edits.sketch === undefined);
  },

  /// `edits` as the share link's text (base64url of the deflate-raw compressed JSON).
  async encode(edits) {
    const stream = new Blob([JSON.stringify(edits)]).stream().pipeThrough(new CompressionStream("deflate-raw"));
    const bytes = new Uint8Array(await new Response(stream).arrayBuffer());
    let binary = "";
    for (let at = 0; at < bytes.length; at += 0x8000) binary += String.fromCharCode(...bytes.subarray(at, at + 0x8000));
    return btoa(binary).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
  },

  /// The edits a share link's text holds; throws when it is not one.
  async decode(text) {
    const binary = atob(text.replace(/-/g, "+").replace(/_/g, "/"));
    const bytes = Uint8Array.from(binary, (c) => c.charCodeAt(0));
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate-raw"));
    const edits = JSON.parse(await new Response(stream).text());
    if (typeof edits !== "object" || typeof (edits.scenarios || {}) !== "object") throw new Error("not a share link");
    return edits;
  },

  /// The link to this page with example `name` and its `edits`.
  async shareLink(name, edits) {
    const base = location.href.replace(/#.*$/, "");
    if (keep.empty(edits)) return `${base}#${encodeURIComponent(name)}`;
    return `${base}#${encodeURIComponent(name)}&${SHARE_KEY}=${await keep.encode(edits)}`;
  },

  /// The example and the shared edits this page's fragment names: {name, shared} (shared: the
  /// share link's text, or null).
  fragment() {
    const [name, ...rest] = location.hash.slice(1).split("&");
    const shared = rest.find((part) => part.startsWith(SHARE_KEY + "="));
    return { name: decodeURIComponent(name || ""), shared: shared ? shared.slice(SHARE_KEY.length + 1) : null };
  },

  /// Saves `text` as a file named `fileName` (the browser's download).
  download(fileName, text) {
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([text], { type: "text/plain" }));
    link.download = fileName;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(link.href), 1000);
  },
});
