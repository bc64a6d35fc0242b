"""The generators stage: retrieval (motion matching), SPAM (one person, body-part masked tokens) and CODA (two people); `router` picks one per request and says why."""
