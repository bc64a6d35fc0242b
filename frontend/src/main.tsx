import { StrictMode } from "react";
import { createRoot } from "react-dom/client";
import { App } from "./App";
import { installTestHook } from "./testHook";
import { adoptLinkedLibrary } from "./library";
import "./styles.css";
import "./ui/panels.css";

installTestHook();
adoptLinkedLibrary(); // a library link (/?library=…) before anything lists or makes motions
createRoot(document.getElementById("root")!).render(
  <StrictMode>
    <App />
  </StrictMode>,
);
