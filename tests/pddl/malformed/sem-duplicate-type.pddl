(define (domain d)
  (:requirements :typing)
  (:types block table
          block))
