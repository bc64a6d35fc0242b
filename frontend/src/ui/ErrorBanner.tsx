import { useStudio } from "../store";

/** The last error (the API's `detail` message), dismissible. */
export function ErrorBanner() {
  const error = useStudio((s) => s.error);
  const setError = useStudio((s) => s.setError);
  if (!error) return null;
  return (
    <div className="error-banner" role="alert" data-testid="error-banner">
      <span className="error-banner__icon" aria-hidden>
        !
      </span>
      <span className="error-banner__text">{error}</span>
      <button className="icon-button" onClick={() => setError(null)} aria-label="Dismiss error">
        ×
      </button>
    </div>
  );
}
