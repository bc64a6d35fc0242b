import { useEffect } from "react";
import { useStudio } from "../store";

/** Dark / light theme (remembered in localStorage), applied as data-theme on <html>. */
export function ThemeToggle() {
  const theme = useStudio((s) => s.theme);
  const setTheme = useStudio((s) => s.setTheme);
  useEffect(() => {
    document.documentElement.dataset.theme = theme;
  }, [theme]);
  const next = theme === "dark" ? "light" : "dark";
  return (
    <button
      className="icon-button"
      data-testid="theme"
      aria-label={`Switch to the ${next} theme`}
      title={`Switch to the ${next} theme`}
      onClick={() => setTheme(next)}
    >
      {theme === "dark" ? "☀" : "☾"}
    </button>
  );
}
